#include "shader/coverage_hints.h"

#include <string_view>
#include <vector>

#include "shader/glsl_lexer.h"

namespace glimmer {
namespace {

// Whether the directive's words include `word` (`#define KILL discard`:
// the macro's body is code wherever it is used).
bool directiveHasWord(std::string_view directive, std::string_view word) {
    const std::vector<GlslToken> w = directiveTokens(directive);
    for (size_t k = 0; k < w.size(); ++k)
        if (isWordToken(directive, w, k, word)) return true;
    return false;
}

}  // namespace

// A pass over the lexer's tokens: a word in a comment is no use; one in a
// directive is a use that cannot be vouched for.
bool keepsPlainTransform(const std::string& vertexText) {
    const std::vector<GlslToken> t = lexGlsl(vertexText);
    int uses = 0;
    bool plain = false;
    for (size_t k = 0; k < t.size(); ++k) {
        if (t[k].kind == GlslTokenKind::Directive && directiveHasWord(tokenText(vertexText, t[k]), "gl_Position")) {
            ++uses;
            plain = false;
        }
        if (!isWordToken(vertexText, t, k, "gl_Position")) continue;
        ++uses;
        // The statement's code, spaces and comments left out, up to its ';';
        // a directive inside it (#ifdef) makes it not plain.
        std::string statement;
        size_t end = k;
        for (; end < t.size() && t[end].kind != GlslTokenKind::Directive; ++end) {
            if (isGlslCode(t[end].kind)) statement += tokenText(vertexText, t[end]);
            if (isPunctToken(vertexText, t, end, ";")) break;
        }
        plain = statement == "gl_Position=gl_ModelViewProjectionMatrix*gl_Vertex;" || statement == "gl_Position=ftransform();";
    }
    return uses == 1 && plain;
}

bool mayDiscard(const std::string& fragmentText) {
    const std::vector<GlslToken> t = lexGlsl(fragmentText);
    for (size_t k = 0; k < t.size(); ++k)
        if (isWordToken(fragmentText, t, k, "discard") ||
            (t[k].kind == GlslTokenKind::Directive && directiveHasWord(tokenText(fragmentText, t[k]), "discard")))
            return true;
    return false;
}

}  // namespace glimmer
