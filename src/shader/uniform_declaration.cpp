#include "shader/uniform_declaration.h"
#include "shader/glsl_scan.h"

#include <cctype>

namespace glimmer {
namespace {

// Whether `word` occurs in `s` from `from` on as a whole word; its end in `at`.
bool hasWord(const std::string& s, const std::string& word, size_t from, size_t& at) {
    for (size_t i = s.find(word, from); i != std::string::npos; i = s.find(word, i + 1)) {
        if (isWholeWordAt(s, i, word.size())) {
            at = i + word.size();
            return true;
        }
    }
    return false;
}

}  // namespace

int uniformDeclarationLine(const std::string& text, const std::string& name) {
    bool inBlockComment = false;
    int line = 1;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        // The line without its comments (a block comment may span lines).
        std::string code;
        for (size_t i = start; i < end; ++i) {
            if (inBlockComment) {
                if (text.compare(i, 2, "*/") == 0) inBlockComment = false, ++i;
                continue;
            }
            if (text.compare(i, 2, "//") == 0) break;
            if (text.compare(i, 2, "/*") == 0) {
                inBlockComment = true;
                ++i;
                continue;
            }
            code += text[i];
        }
        size_t afterUniform = 0, afterName = 0;
        if (hasWord(code, "uniform", 0, afterUniform) && hasWord(code, name, afterUniform, afterName)) {
            size_t semicolon = code.find(';', afterUniform);
            if (semicolon == std::string::npos || afterName <= semicolon) return line;
        }
        if (end == text.size()) break;
        start = end + 1;
        ++line;
    }
    return 0;
}

}  // namespace glimmer
