#include "shader/coverage_hints.h"
#include "shader/glsl_scan.h"

#include <cctype>

namespace glimmer {
namespace {

// Positions where `word` appears as a whole identifier.
template <typename F>
void forEachWord(const std::string& text, const std::string& word, F f) {
    for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
        if (isWholeWordAt(text, at, word.size())) f(at);
    }
}

std::string withoutSpaces(const std::string& s) {
    std::string out;
    for (char c : s)
        if (!std::isspace(static_cast<unsigned char>(c))) out += c;
    return out;
}

}  // namespace

bool keepsPlainTransform(const std::string& vertexText) {
    int uses = 0;
    bool plain = false;
    forEachWord(vertexText, "gl_Position", [&](size_t at) {
        ++uses;
        size_t end = vertexText.find(';', at);
        if (end == std::string::npos) return;
        const std::string statement = withoutSpaces(vertexText.substr(at, end - at + 1));
        plain = statement == "gl_Position=gl_ModelViewProjectionMatrix*gl_Vertex;" ||
                statement == "gl_Position=ftransform();";
    });
    return uses == 1 && plain;
}

bool mayDiscard(const std::string& fragmentText) {
    bool found = false;
    forEachWord(fragmentText, "discard", [&](size_t) { found = true; });
    return found;
}

}  // namespace glimmer
