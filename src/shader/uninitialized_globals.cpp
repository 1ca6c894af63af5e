#include "shader/uninitialized_globals.h"

#include <set>
#include <string_view>
#include <vector>

#include "shader/glsl_lexer.h"

namespace glimmer {
namespace {

// The shader's code tokens (no comments, no directives) and the text they
// point into; every look below is at whole tokens, never at characters.
struct Code {
    std::string_view text;
    std::vector<GlslToken> t;
    bool punct(size_t k, std::string_view p) const { return isPunctToken(text, t, k, p); }
    bool word(size_t k) const { return k < t.size() && t[k].kind == GlslTokenKind::Word; }
    std::string_view at(size_t k) const { return tokenText(text, t[k]); }
    // Whether a word of tokens [from, to) is `name` / one of `names`.
    bool hasWord(size_t from, size_t to, std::string_view name) const {
        for (size_t k = from; k < to; ++k)
            if (word(k) && at(k) == name) return true;
        return false;
    }
    bool hasWordIn(size_t from, size_t to, const std::set<std::string, std::less<>>& names) const {
        for (size_t k = from; k < to; ++k)
            if (word(k) && names.count(at(k))) return true;
        return false;
    }
};

struct Function {
    std::string name;
    size_t open = 0, close = 0;  // tokens of its body's braces
};

// Whether the statement of tokens [k, to) (one of main's, at its top level)
// starts by assigning `name` (`name = ...`, `name.xy = ...`, `name[i] = ...`).
bool assigns(const Code& c, const std::vector<size_t>& mate, size_t k, size_t to, std::string_view name) {
    if (k >= to || !c.word(k) || c.at(k) != name) return false;
    ++k;
    while (k < to && (c.word(k) || c.punct(k, "."))) ++k;
    if (k < to && c.punct(k, "[")) {
        if (mate[k] == std::string_view::npos || mate[k] >= to) return false;
        k = mate[k] + 1;
    }
    return k < to && c.punct(k, "=");  // the lexer reads "==" and "+=" as tokens of their own
}

}  // namespace

int globalSetByMainFirst(const std::string& text, const std::string& name, int warningLine) {
    const Code c{text, glslCodeTokens(text)};
    const std::vector<size_t> mate = matchingBrackets(text, c.t);
    // File scope: function bodies and the declarations between them.
    std::vector<Function> functions;
    bool isGlobal = false;
    size_t stmtStart = 0;
    int depth = 0;
    for (size_t k = 0; k < c.t.size(); ++k) {
        if (c.punct(k, "{")) {
            if (depth++ != 0) continue;
            size_t paren = stmtStart;  // a function's head: ... NAME ( ... ) {
            while (paren < k && !c.punct(paren, "(")) ++paren;
            for (size_t w = paren; paren < k && w > stmtStart; --w)
                if (c.word(w - 1)) {
                    functions.push_back({std::string(c.at(w - 1)), k, 0});
                    break;
                }
        } else if (c.punct(k, "}")) {
            if (--depth == 0) {
                if (!functions.empty() && functions.back().close == 0) functions.back().close = k;
                stmtStart = k + 1;
            }
            if (depth < 0) return 0;
        } else if (c.punct(k, ";") && depth == 0) {
            static const std::set<std::string, std::less<>> notPlain = {
                "uniform", "in", "out", "inout", "attribute", "varying", "const", "layout", "buffer", "shared", "struct"};
            size_t first = stmtStart, paren = stmtStart;
            while (first < k && !c.word(first)) ++first;
            while (paren < k && !c.punct(paren, "(")) ++paren;
            if (first < k && !notPlain.count(c.at(first)) && paren == k && c.hasWord(stmtStart, k, name)) isGlobal = true;
            stmtStart = k + 1;
        }
    }
    if (!isGlobal) return 0;
    const Function* main = nullptr;
    const Function* reader = nullptr;
    for (const auto& f : functions) {
        if (f.name == "main") main = &f;
        if (f.close && c.t[f.open].line <= warningLine && warningLine <= c.t[f.close].line) reader = &f;
    }
    if (!main || !main->close || !reader || reader == main) return 0;
    std::set<std::string, std::less<>> defined;
    for (const auto& f : functions)
        if (f.name != "main") defined.insert(f.name);
    // main's statements at its top level, in order: the first that sets the
    // global must come before the first that calls a function of the shader.
    int inner = 0, parens = 0;
    size_t start = main->open + 1;
    for (size_t k = main->open + 1; k < main->close; ++k) {
        parens += c.punct(k, "(") ? 1 : c.punct(k, ")") ? -1 : 0;
        inner += c.punct(k, "{") ? 1 : c.punct(k, "}") ? -1 : 0;
        const bool semicolon = c.punct(k, ";");
        if (!(semicolon && inner == 0 && parens == 0) && !(c.punct(k, "}") && inner == 0)) continue;
        // Its right-hand side must not call one either.
        if (inner == 0 && semicolon && assigns(c, mate, start, k, name) && !c.hasWordIn(start, k, defined))
            return c.t[start].line;
        if (c.hasWordIn(start, k + 1, defined) || c.hasWord(start, k + 1, name)) return 0;  // a call first, or a read of it
        start = k + 1;
    }
    return 0;
}

}  // namespace glimmer
