#include "shader/uniform_declaration.h"

#include <string_view>
#include <vector>

#include "shader/glsl_lexer.h"

namespace glimmer {
namespace {

// Whether code tokens `t` of `text` hold `uniform` and then `name` on the
// same line, before the ';' that ends it; its line in `line`.
bool declares(std::string_view text, const std::vector<GlslToken>& t, std::string_view name, int& line) {
    for (size_t k = 0; k < t.size(); ++k) {
        if (!isWordToken(text, t, k, "uniform")) continue;
        // A declaration split over lines is not found: the warning shows one line.
        for (size_t n = k + 1; n < t.size() && t[n].line == t[k].line && !isPunctToken(text, t, n, ";"); ++n)
            if (isWordToken(text, t, n, name)) {
                line = t[k].line;
                return true;
            }
    }
    return false;
}

}  // namespace

// A pass over the lexer's tokens: comments are skipped; a directive's words
// are read too (`#define DECLARE uniform float uKd;` is where it is written).
// A directive has lines of its own, so the code before it is read first.
int uniformDeclarationLine(const std::string& text, const std::string& name) {
    std::vector<GlslToken> code;
    int line = 0;
    for (const GlslToken& t : lexGlsl(text)) {
        if (isGlslCode(t.kind)) code.push_back(t);
        if (t.kind != GlslTokenKind::Directive) continue;
        if (declares(text, code, name, line)) return line;
        code.clear();
        const std::string_view directive = tokenText(text, t);
        if (declares(directive, directiveTokens(directive), name, line)) return t.line + line - 1;  // of its own lines
    }
    return declares(text, code, name, line) ? line : 0;
}

}  // namespace glimmer
