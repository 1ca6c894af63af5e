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
    // Comments become blanks, as the compiler reads them (a block comment may
    // span lines; the line numbers stay).
    const std::string code = blankComments(text);
    int line = 1;
    for (size_t start = 0; start <= code.size(); ++line) {
        size_t end = code.find('\n', start);
        if (end == std::string::npos) end = code.size();
        const std::string one = code.substr(start, end - start);
        size_t afterUniform = 0, afterName = 0;
        if (hasWord(one, "uniform", 0, afterUniform) && hasWord(one, name, afterUniform, afterName)) {
            size_t semicolon = one.find(';', afterUniform);
            if (semicolon == std::string::npos || afterName <= semicolon) return line;
        }
        if (end == code.size()) break;
        start = end + 1;
    }
    return 0;
}

}  // namespace glimmer
