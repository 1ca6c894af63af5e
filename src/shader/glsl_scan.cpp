#include "shader/glsl_scan.h"

#include <algorithm>

#include "shader/glsl_lexer.h"

namespace glimmer {
namespace {

bool isDigits(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The number of a #version directive's Number token: its leading digits,
// saturated (never std::stoi, which throws on 20 digits); -1 when none.
int versionNumber(std::string_view number) {
    long long n = 0;
    size_t k = 0;
    for (; k < number.size() && number[k] >= '0' && number[k] <= '9'; ++k)
        n = std::min<long long>(n * 10 + (number[k] - '0'), kMaxGlslVersionNumber);
    return k == 0 ? -1 : int(n);
}

}  // namespace

// The first Directive token of the lexer whose first word is `version`: a
// directive in a comment is inside the comment's token, so it never counts.
// Lexed only up to it: it is near the top, and callers ask on every build.
GlslVersion glslVersionOf(std::string_view s) {
    GlslVersion v;
    GlslLexer lexer(s);
    for (GlslToken t{}; lexer.next(t);) {
        if (t.kind != GlslTokenKind::Directive) continue;
        const std::string_view d = tokenText(s, t);
        const std::vector<GlslToken> w = directiveTokens(d);  // version NUMBER [PROFILE], comments left out
        if (!isWordToken(d, w, 0, "version")) continue;
        v.line = t.line;
        size_t k = 1;
        const int number = k < w.size() && w[k].kind == GlslTokenKind::Number ? versionNumber(tokenText(d, w[k])) : -1;
        if (number >= 0) v.number = number;
        v.wellFormed = number >= 0 && isDigits(tokenText(d, w[k]));  // not "150core", "1.5"
        if (number >= 0) v.numberEnd = t.begin + w[k++].end;
        if (k < w.size() && w[k].kind == GlslTokenKind::Word) v.profile = std::string(tokenText(d, w[k++]));
        if (k < w.size()) v.wellFormed = false;  // anything after the profile
        return v;
    }
    return v;
}

size_t lineStartOf(std::string_view text, int line) {
    size_t at = 0;
    for (int n = 1; n < line; ++n) {
        at = text.find('\n', at);
        if (at == std::string_view::npos) return at;
        ++at;
    }
    return at;
}

std::string_view lineOf(std::string_view text, int line) {
    const size_t at = lineStartOf(text, line);
    if (at == std::string_view::npos || at > text.size()) return {};
    const size_t end = text.find('\n', at);
    return text.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at);
}

std::string firstWordWithPrefix(std::string_view text, std::string_view prefix) {
    if (prefix.empty()) return {};
    for (size_t at = text.find(prefix); at != std::string_view::npos; at = text.find(prefix, at + 1)) {
        if (at > 0 && isGlslWordChar(text[at - 1])) continue;  // inside a longer word
        size_t end = at + prefix.size();
        while (end < text.size() && isGlslWordChar(text[end])) ++end;
        if (end > at + prefix.size()) return std::string(text.substr(at, end - at));
    }
    return {};
}

std::string globalConstDropped(const std::string& quoted) {
    return quoted + " is a const outside any function set from a non-constant expression: 'const' dropped, so it is "
                    "set when the shader starts, as NVIDIA's driver does; remove 'const' to run everywhere";
}

// The last code token `const` on the line before the column: one in a
// comment or a directive is not the declaration's. Lexed only up to there.
std::string withoutConstBefore(std::string text, int line, int col) {
    size_t at = std::string::npos;
    GlslLexer lexer(text);
    for (GlslToken t{}; lexer.next(t);) {
        if (t.line > line || (t.line == line && t.col >= col)) break;
        if (t.line == line && t.kind == GlslTokenKind::Word && tokenText(text, t) == "const") at = t.begin;
    }
    if (at != std::string::npos) text.replace(at, 5, "     ");
    return text;
}

}  // namespace glimmer
