#include "shader/glsl_scan.h"

#include <algorithm>

namespace glimmer {
namespace {

size_t skipBlanks(std::string_view s, size_t i) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
    return i;
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Reads the directive's words after "#version" on line `l` (from `p`).
void readVersion(std::string_view l, size_t p, GlslVersion& v) {
    p = skipBlanks(l, p);
    long long n = 0;
    size_t digits = p;
    while (p < l.size() && isDigit(l[p])) {
        n = n * 10 + (l[p] - '0');
        if (n > kMaxGlslVersionNumber) n = kMaxGlslVersionNumber;  // saturate: never overflow
        ++p;
    }
    if (p > digits) v.number = int(n);
    else v.wellFormed = false;
    p = skipBlanks(l, p);
    size_t q = p;
    while (q < l.size() && isGlslWordChar(l[q])) ++q;
    v.profile = std::string(l.substr(p, q - p));
    q = skipBlanks(l, q);
    if (q < l.size() && l.compare(q, 2, "//") != 0) v.wellFormed = false;
}

}  // namespace

size_t commentEnd(std::string_view s, size_t i) {
    if (i + 1 >= s.size() || s[i] != '/') return i;
    if (s[i + 1] == '/') {
        size_t end = s.find('\n', i);
        return end == std::string_view::npos ? s.size() : end;
    }
    if (s[i + 1] == '*') {
        size_t end = s.find("*/", i + 2);
        return end == std::string_view::npos ? s.size() : end + 2;
    }
    return i;
}

std::string blankComments(std::string_view text) {
    std::string s(text);
    for (size_t i = 0; i < s.size();) {
        size_t end = commentEnd(s, i);
        if (end == i) {
            ++i;
            continue;
        }
        for (; i < end; ++i)
            if (s[i] != '\n') s[i] = ' ';
    }
    return s;
}

bool isWholeWordAt(std::string_view text, size_t at, size_t length) {
    if (at > text.size() || length > text.size() - at) return false;
    bool before = at > 0 && isGlslWordChar(text[at - 1]);
    bool after = at + length < text.size() && isGlslWordChar(text[at + length]);
    return !before && !after;
}

GlslVersion glslVersionOf(std::string_view s) {
    GlslVersion v;
    size_t lineStart = 0;
    int line = 1;
    bool inBlockComment = false;
    while (lineStart <= s.size()) {
        size_t end = s.find('\n', lineStart);
        if (end == std::string_view::npos) end = s.size();
        std::string_view l = s.substr(lineStart, end - lineStart);
        if (!inBlockComment) {
            size_t p = skipBlanks(l, 0);
            if (p < l.size() && l[p] == '#') {
                p = skipBlanks(l, p + 1);
                if (l.compare(p, 7, "version") == 0 && (p + 7 == l.size() || !isGlslWordChar(l[p + 7]))) {
                    readVersion(l, p + 7, v);
                    v.line = line;
                    return v;
                }
            }
        }
        // Only a block comment may hide a #version line.
        for (size_t k = 0; k + 1 < l.size(); ++k) {
            if (!inBlockComment && l[k] == '/' && l[k + 1] == '/') break;
            if (!inBlockComment && l[k] == '/' && l[k + 1] == '*') inBlockComment = true, ++k;
            else if (inBlockComment && l[k] == '*' && l[k + 1] == '/') inBlockComment = false, ++k;
        }
        lineStart = end + 1;
        ++line;
    }
    return v;
}

std::vector<std::string_view> glslWords(std::string_view text) {
    std::vector<std::string_view> out;
    for (size_t i = 0; i < text.size();) {
        if (!isGlslWordChar(text[i])) {
            ++i;
            continue;
        }
        size_t j = i;
        while (j < text.size() && isGlslWordChar(text[j])) ++j;
        out.push_back(text.substr(i, j - i));
        i = j;
    }
    return out;
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

std::string withoutConstBefore(std::string text, int line, int col) {
    const size_t start = lineStartOf(text, line);
    if (start == std::string::npos) return text;
    size_t end = std::min(text.find('\n', start), start + size_t(std::max(col - 1, 0)));
    if (end == std::string::npos) end = text.size();
    for (size_t at = text.rfind("const", end); at != std::string::npos && at >= start;
         at = at == 0 ? std::string::npos : text.rfind("const", at - 1)) {
        if (isWholeWordAt(text, at, 5)) {
            text.replace(at, 5, "     ");
            break;
        }
    }
    return text;
}

}  // namespace glimmer
