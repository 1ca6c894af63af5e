#include "shader/precision_strip.h"
#include "shader/glsl_scan.h"

#include <cctype>
#include <cstdlib>

namespace glimmer {
namespace {

// The shader's #version number; 110 when it has none.
int versionOf(std::string_view s) {
    size_t at = 0;
    while ((at = s.find("#version", at)) != std::string_view::npos) {
        size_t lineStart = s.rfind('\n', at);
        lineStart = lineStart == std::string_view::npos ? 0 : lineStart + 1;
        bool first = true;  // only blanks before '#' on its line
        for (size_t i = lineStart; i < at; ++i) first &= s[i] == ' ' || s[i] == '\t';
        if (first) return std::atoi(std::string(s.substr(at + 8, 16)).c_str());
        at += 8;
    }
    return 110;
}

}  // namespace

PrecisionStripResult stripPrecisionQualifiers(std::string_view source) {
    PrecisionStripResult r;
    r.text.assign(source);
    if (versionOf(source) >= 130) return r;
    std::string& t = r.text;
    int line = 1;
    bool lineStart = true;
    auto blank = [&](size_t from, size_t to) {
        for (size_t k = from; k < to; ++k)
            if (t[k] != '\n') t[k] = ' ';
        if (!r.firstLine) r.firstLine = line;
    };
    for (size_t i = 0; i < t.size();) {
        char c = t[i];
        if (c == '\n') {
            ++line;
            lineStart = true;
            ++i;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r') {
            ++i;
            continue;
        }
        if (lineStart && c == '#') {  // a preprocessor line, continuations included
            while (i < t.size() && !(t[i] == '\n' && t[i - 1] != '\\')) ++i;
            continue;
        }
        lineStart = false;
        if (size_t end = commentEnd(t, i); end != i) {
            for (; i < end; ++i) line += t[i] == '\n';
            continue;
        }
        if (!isGlslWordChar(c) || std::isdigit(static_cast<unsigned char>(c))) {
            ++i;
            while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i - 1])) && isGlslWordChar(t[i])) ++i;
            continue;
        }
        size_t j = i;
        while (j < t.size() && isGlslWordChar(t[j])) ++j;
        std::string_view word(t.data() + i, j - i);
        if (word == "precision") {
            size_t end = t.find(';', j);  // `precision highp float;`
            if (end == std::string::npos) end = t.size() - 1;
            int lines = 0;
            for (size_t k = i; k <= end; ++k) lines += t[k] == '\n';
            blank(i, end + 1);
            line += lines;
            i = end + 1;
            continue;
        }
        if (word == "highp" || word == "mediump" || word == "lowp") blank(i, j);
        i = j;
    }
    return r;
}

}  // namespace glimmer
