#include "shader/uniform_initializers.h"

#include <algorithm>

#include "shader/glsl_lexer.h"
#include "util/numbers.h"

namespace glimmer {
namespace {

// Components of a scalar or vector type; 0 for any other.
int components(std::string_view type) {
    if (type == "float" || type == "int" || type == "uint" || type == "bool") return 1;
    for (std::string_view prefix : {"vec", "ivec", "uvec", "bvec"})
        if (type.size() == prefix.size() + 1 && type.substr(0, prefix.size()) == prefix) {
            char n = type.back();
            if (n >= '2' && n <= '4') return n - '0';
        }
    return 0;
}

// The code tokens of one value, [from, to) of `tokens`, read from `text`.
struct Value {
    std::string_view text;
    const std::vector<GlslToken>& tokens;
    size_t from, to;
    bool punct(size_t k, std::string_view p) const { return k < to && isPunctToken(text, tokens, k, p); }
    std::string_view at(size_t k) const { return tokenText(text, tokens[k]); }
};

// One constant at token `k`: true, false, or a Number with an optional '-'
// before it. `k` moves past it; false when there is none.
bool number(const Value& v, size_t& k, float& out) {
    if (k < v.to && v.tokens[k].kind == GlslTokenKind::Word && (v.at(k) == "true" || v.at(k) == "false")) {
        out = v.at(k++) == "true" ? 1.f : 0.f;
        return true;
    }
    const bool minus = v.punct(k, "-");
    const size_t n = k + (minus ? 1 : 0);
    if (n >= v.to || v.tokens[n].kind != GlslTokenKind::Number) return false;
    std::string_view s = v.at(n);
    if (s.back() == 'f' || s.back() == 'F' || s.back() == 'u' || s.back() == 'U') s.remove_suffix(1);
    if (s.empty() || s.size() > 64) return false;
    double d = 0;  // never strtof: in a decimal-comma locale it stops at the '.'
    ParsedNumber p = parseDouble(s.data(), s.data() + s.size(), d);
    if (p.ec != std::errc() || p.end != s.data() + s.size() || !(d >= 0 && d <= 3.4e38)) return false;
    out = float(minus ? -d : d);
    k = n + 1;
    return true;
}

// The values of a `type` set to `v`; false when it is not a plain constant
// or a constructor of one ("vec3(0., .5, 1.)", "vec4(.25)").
bool readValue(std::string_view type, const Value& v, std::vector<float>& values) {
    const int n = components(type);
    size_t k = v.from;
    float x = 0;
    if (n == 0) return false;
    if (number(v, k, x)) {
        values = {x};
        return n == 1 && k == v.to;
    }
    if (k >= v.to || v.tokens[k].kind != GlslTokenKind::Word || components(v.at(k)) != n || !v.punct(k + 1, "(") ||
        !v.punct(v.to - 1, ")"))
        return false;
    for (k += 2; k < v.to; ++k) {  // number, ',' ... ')'
        if (!number(v, k, x)) return false;
        values.push_back(x);
        if (!v.punct(k, ",")) break;
    }
    if (k != v.to - 1) return false;
    if (values.size() == 1 && n > 1) values.assign(size_t(n), values[0]);  // vec3(1.)
    return int(values.size()) == n;
}

}  // namespace

// One pass over the lexer's code tokens (comments and directives are not
// among them): at brace depth 0 each `uniform` statement is split into its
// declarators, and each " = VALUE" is read and blanked by offsets.
UniformInitializers takeUniformInitializers(std::string_view source) {
    UniformInitializers out;
    const std::vector<GlslToken> t = glslCodeTokens(source);
    auto punct = [&](size_t k, std::string_view p) { return isPunctToken(source, t, k, p); };
    std::vector<GlslEdit> blanks;
    int depth = 0;  // of braces: only declarations at file scope are uniforms
    for (size_t k = 0; k < t.size(); ++k) {
        if (punct(k, "{")) ++depth;
        if (punct(k, "}") && depth > 0) --depth;
        if (depth != 0 || !isWordToken(source, t, k, "uniform")) continue;
        // The statement: up to ';' at parenthesis depth 0 (a block's braces end it too).
        size_t stop = k + 1;
        for (int parens = 0; stop < t.size() && !(parens == 0 && (punct(stop, ";") || punct(stop, "{"))); ++stop)
            parens += punct(stop, "(") ? 1 : punct(stop, ")") ? -1 : 0;
        if (stop >= t.size()) break;  // no end
        if (punct(stop, "{")) {       // a uniform block: its '{' is counted next
            k = stop - 1;
            continue;
        }
        // Declarators split at depth-0 commas: the first carries the type.
        std::string type;
        int parens = 0;
        for (size_t from = k + 1, d = from; d <= stop; ++d) {
            parens += d < stop && punct(d, "(") ? 1 : d < stop && punct(d, ")") ? -1 : 0;
            if (d < stop && !(parens == 0 && punct(d, ","))) continue;
            size_t eq = from, bracket = d;
            while (eq < d && !punct(eq, "=")) ++eq;
            for (size_t w = from; w < eq && bracket == d; ++w)
                if (punct(w, "[")) bracket = w;
            // The words before '=' (and an array's size): [precision] TYPE NAME, or NAME after a comma.
            std::vector<std::string_view> words;
            for (size_t w = from; w < std::min(eq, bracket); ++w)
                if (t[w].kind == GlslTokenKind::Word) words.push_back(tokenText(source, t[w]));
            if (type.empty() && words.size() >= 2) type = std::string(words[words.size() - 2]);
            if (eq < d && !words.empty()) {
                UniformInitializer u;
                u.name = std::string(words.back());
                u.type = type;
                u.line = t[eq + 1].line;  // the value's first token, or the ',' or ';' when there is none
                u.col = t[eq + 1].col;
                if (bracket == d && readValue(type, Value{source, t, eq + 1, d}, u.values)) out.values.push_back(std::move(u));
                else out.unreadable.push_back(std::move(u));
                // Blanked from '=' to the ',' or ';', comments and all; newlines kept.
                blanks.push_back(blankingEdit(source, t[eq].begin, t[d].begin));
            }
            from = d + 1;
        }
        k = stop;
    }
    out.text = applyGlslEdits(source, std::move(blanks));
    return out;
}

}  // namespace glimmer
