// The GLSL lexer (shader/glsl_lexer.h). Held by test_shader's lexer cases
// and, for a directive's end, by test_cli's
// CliWatch.ABlockCommentAfterADivisionInADefineEndsWhereItsStarSlashIs: a
// '/' of division is no comment (issue 40; docs/RELIABILITY.md).
#include "shader/glsl_lexer.h"

#include <algorithm>

#include "shader/glsl_scan.h"

namespace glimmer {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// The operators of more than one character, longest first where one is the
// start of another ("<<=" before "<<").
constexpr std::string_view kLongOperators[] = {"<<=", ">>=", "++", "--", "<<", ">>", "<=", ">=", "==", "!=", "&&",
                                               "||",  "^^",  "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^="};
constexpr std::string_view kPunctuators = "()[]{}.,;:?+-*/%<>=!~&|^";

// Where the block comment that starts at `at` ("/*") ends: past its "*/",
// or the text's end when it never closes.
size_t blockCommentEnd(std::string_view s, size_t at) {
    const size_t close = s.find("*/", at + 2);
    return close == std::string_view::npos ? s.size() : close + 2;
}

// Where the directive that starts at `at` ('#') ends: at the newline (or
// "\r\n") that is neither continued by a '\' nor inside a block comment
// opened in the directive; the text's end when there is none.
size_t directiveEnd(std::string_view s, size_t at) {
    bool inLineComment = false;  // after "//", a "/*" opens nothing
    size_t i = at + 1;
    while (i < s.size()) {
        const char c = s[i];
        if (c == '\n') {
            size_t before = i;  // the '\' of a continuation may stand before "\r\n" too
            if (before > at && s[before - 1] == '\r') --before;
            if (before > at && s[before - 1] == '\\') {
                ++i;
                continue;
            }
            return before;
        }
        if (!inLineComment && c == '/' && i + 1 < s.size() && s[i + 1] == '/') inLineComment = true;
        if (!inLineComment && c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            i = blockCommentEnd(s, i);
            continue;
        }
        ++i;
    }
    return s.size();
}

// Where the number that starts at `at` ends (see the header: a pp-number).
size_t numberEnd(std::string_view s, size_t at) {
    const bool hex = s[at] == '0' && at + 1 < s.size() && (s[at + 1] == 'x' || s[at + 1] == 'X');
    size_t i = at + 1;
    while (i < s.size()) {
        const char c = s[i];
        const bool sign = (c == '+' || c == '-') && !hex && (s[i - 1] == 'e' || s[i - 1] == 'E');
        if (!isGlslWordChar(c) && c != '.' && !sign) break;
        ++i;
    }
    return i;
}

// How long the operator or punctuator at `at` is; 0 when none starts there.
size_t punctLength(std::string_view s, size_t at) {
    for (std::string_view op : kLongOperators)
        if (s.compare(at, op.size(), op) == 0) return op.size();
    return kPunctuators.find(s[at]) != std::string_view::npos ? 1 : 0;
}

}  // namespace

bool GlslLexer::next(GlslToken& out) {
    const std::string_view s = s_;
    const size_t i = i_;
    if (i >= s.size()) return false;
    const char c = s[i];
    GlslToken t{GlslTokenKind::Other, i, i + 1, line_, int(i - lineBegin_) + 1};
    if (c == '\n' || (c == '\r' && i + 1 < s.size() && s[i + 1] == '\n')) {
        t.kind = GlslTokenKind::Newline;
        t.end = c == '\n' ? i + 1 : i + 2;
    } else if (isBlank(c)) {
        t.kind = GlslTokenKind::Space;
        while (t.end < s.size() && isBlank(s[t.end]) && !(s[t.end] == '\r' && t.end + 1 < s.size() && s[t.end + 1] == '\n'))
            ++t.end;
    } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
        t.kind = GlslTokenKind::LineComment;
        t.end = std::min(s.find('\n', i), s.size());
        if (t.end > i + 2 && s[t.end - 1] == '\r' && t.end < s.size()) --t.end;  // "\r\n" is the Newline's
    } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
        t.kind = GlslTokenKind::BlockComment;
        t.end = blockCommentEnd(s, i);
    } else if (c == '#' && atLineStart_) {
        t.kind = GlslTokenKind::Directive;
        t.end = directiveEnd(s, i);
    } else if (isGlslWordStart(c)) {
        t.kind = GlslTokenKind::Word;
        while (t.end < s.size() && isGlslWordChar(s[t.end])) ++t.end;
    } else if (isDigit(c) || (c == '.' && i + 1 < s.size() && isDigit(s[i + 1]))) {
        t.kind = GlslTokenKind::Number;
        t.end = numberEnd(s, i);
    } else if (size_t length = punctLength(s, i); length > 0) {
        t.kind = GlslTokenKind::Punct;
        t.end = i + length;
    }
    if (t.kind == GlslTokenKind::Newline) atLineStart_ = true;
    else if (t.kind != GlslTokenKind::Space && t.kind != GlslTokenKind::BlockComment) atLineStart_ = false;
    // Only newlines, block comments and directives hold a '\n'.
    if (t.kind == GlslTokenKind::Newline || t.kind == GlslTokenKind::BlockComment || t.kind == GlslTokenKind::Directive)
        for (size_t k = i; k < t.end; ++k)
            if (s[k] == '\n') ++line_, lineBegin_ = k + 1;
    i_ = t.end;
    out = t;
    return true;
}

std::vector<GlslToken> lexGlsl(std::string_view s) {
    std::vector<GlslToken> out;
    GlslLexer lexer(s);
    for (GlslToken t{}; lexer.next(t);) out.push_back(t);
    return out;
}

std::vector<GlslToken> glslCodeTokens(std::string_view text) {
    std::vector<GlslToken> all = lexGlsl(text);
    all.erase(std::remove_if(all.begin(), all.end(), [](const GlslToken& t) { return !isGlslCode(t.kind); }), all.end());
    return all;
}

std::vector<GlslToken> directiveTokens(std::string_view directive) {
    if (directive.empty() || directive[0] != '#') return {};
    // A blank in its place keeps offsets, and a '#' again cannot start a
    // directive. A '\' that continues a line is a blank too, as for the
    // preprocessor ("#version \<newline> 150" is version, 150).
    std::string rest(directive);
    rest[0] = ' ';
    for (size_t k = 0; k < rest.size(); ++k)
        if (rest[k] == '\\' && (rest.compare(k + 1, 1, "\n") == 0 || rest.compare(k + 1, 2, "\r\n") == 0)) rest[k] = ' ';
    return glslCodeTokens(rest);
}

bool isWordToken(std::string_view text, const std::vector<GlslToken>& tokens, size_t k, std::string_view word) {
    return k < tokens.size() && tokens[k].kind == GlslTokenKind::Word && tokenText(text, tokens[k]) == word;
}

bool isPunctToken(std::string_view text, const std::vector<GlslToken>& tokens, size_t k, std::string_view punct) {
    return k < tokens.size() && tokens[k].kind == GlslTokenKind::Punct && tokenText(text, tokens[k]) == punct;
}

std::vector<size_t> matchingBrackets(std::string_view text, const std::vector<GlslToken>& tokens) {
    std::vector<size_t> mate(tokens.size(), std::string_view::npos);
    std::vector<size_t> open;
    for (size_t k = 0; k < tokens.size(); ++k) {
        if (tokens[k].kind != GlslTokenKind::Punct || tokens[k].end - tokens[k].begin != 1) continue;
        const char c = text[tokens[k].begin];
        if (c == '(' || c == '[' || c == '{') {
            open.push_back(k);
            continue;
        }
        const char opener = c == ')' ? '(' : c == ']' ? '[' : c == '}' ? '{' : 0;
        if (opener && !open.empty() && text[tokens[open.back()].begin] == opener) {
            mate[k] = open.back();
            mate[open.back()] = k;
            open.pop_back();
        }
    }
    return mate;
}

GlslEdit blankingEdit(std::string_view text, size_t begin, size_t end) {
    GlslEdit e{begin, end - begin, std::string(text.substr(begin, end - begin))};
    for (char& c : e.insert)
        if (c != '\n') c = ' ';
    return e;
}

std::string applyGlslEdits(std::string_view text, std::vector<GlslEdit> edits) {
    std::stable_sort(edits.begin(), edits.end(), [](const GlslEdit& a, const GlslEdit& b) { return a.at < b.at; });
    std::string out;
    out.reserve(text.size());
    size_t pos = 0;
    for (const GlslEdit& e : edits) {
        if (e.at < pos || e.at > text.size()) continue;  // overlapping: see the header
        out.append(text.substr(pos, e.at - pos));
        out += e.insert;
        pos = std::min(text.size(), e.at + e.erase);
    }
    if (pos < text.size()) out.append(text.substr(pos));
    return out;
}

}  // namespace glimmer
