#include "shader/uniform_initializers.h"


#include "shader/glsl_scan.h"
#include "util/numbers.h"

namespace glimmer {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
    while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
    return s;
}

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

bool number(std::string_view s, float& out) {
    s = trim(s);
    if (s == "true" || s == "false") {
        out = s == "true" ? 1.f : 0.f;
        return true;
    }
    if (!s.empty() && (s.back() == 'f' || s.back() == 'F' || s.back() == 'u' || s.back() == 'U')) s.remove_suffix(1);
    if (s.empty() || s.size() > 64) return false;
    double v = 0;  // never strtof: in a decimal-comma locale it stops at the '.'
    ParsedNumber p = parseDouble(s.data(), s.data() + s.size(), v);
    if (p.ec != std::errc() || p.end != s.data() + s.size() || !(v >= -3.4e38 && v <= 3.4e38)) return false;
    out = float(v);
    return true;
}

// The values of `init` for a `type`; false when it is not a plain constant.
bool readValue(std::string_view type, std::string_view init, std::vector<float>& values) {
    const int n = components(type);
    if (n == 0) return false;
    init = trim(init);
    float v = 0;
    if (number(init, v)) {
        if (n != 1) return false;
        values = {v};
        return true;
    }
    size_t open = init.find('(');
    if (open == std::string_view::npos || init.back() != ')' || components(trim(init.substr(0, open))) != n) return false;
    std::string_view args = init.substr(open + 1, init.size() - open - 2);
    for (size_t at = 0; at <= args.size();) {
        size_t comma = args.find(',', at);
        if (comma == std::string_view::npos) comma = args.size();
        if (!number(args.substr(at, comma - at), v)) return false;
        values.push_back(v);
        at = comma + 1;
    }
    if (values.size() == 1 && n > 1) values.assign(size_t(n), values[0]);  // vec3(1.)
    return int(values.size()) == n;
}

struct Place {
    int line, col;
};

}  // namespace

UniformInitializers takeUniformInitializers(std::string_view source) {
    UniformInitializers out;
    out.text = std::string(source);
    std::string& s = out.text;
    // Line and column of every offset are found by counting as we go.
    std::vector<size_t> lineStarts{0};
    for (size_t i = 0; i < s.size(); ++i)
        if (s[i] == '\n') lineStarts.push_back(i + 1);
    auto placeOf = [&](size_t at) {
        size_t lo = 0, hi = lineStarts.size();
        while (hi - lo > 1) {
            size_t mid = (lo + hi) / 2;
            (lineStarts[mid] <= at ? lo : hi) = mid;
        }
        return Place{int(lo + 1), int(at - lineStarts[lo] + 1)};
    };
    int depth = 0;  // of braces: only declarations at file scope are uniforms
    bool lineStart = true;
    for (size_t i = 0; i < s.size();) {
        const char c = s[i];
        if (size_t end = commentEnd(s, i); end != i) {
            i = end;
            continue;
        }
        if (c == '#' && lineStart) {  // a preprocessor line (continued lines aside)
            i = s.find('\n', i);
            if (i == std::string::npos) break;
            continue;
        }
        if (c == '\n') lineStart = true;
        else if (!isBlank(c)) lineStart = false;
        if (c == '{') ++depth;
        if (c == '}' && depth > 0) --depth;
        if (!isGlslWordStart(c) || (i > 0 && isGlslWordChar(s[i - 1]))) {
            ++i;
            continue;
        }
        size_t end = i;
        while (end < s.size() && isGlslWordChar(s[end])) ++end;
        if (depth != 0 || s.compare(i, end - i, "uniform") != 0) {
            i = end;
            continue;
        }
        // The statement: up to ';' at parenthesis depth 0 (a block's braces end it too).
        size_t stop = end;
        int parens = 0;
        while (stop < s.size() && !(parens == 0 && (s[stop] == ';' || s[stop] == '{'))) {
            parens += s[stop] == '(';
            parens -= s[stop] == ')';
            ++stop;
        }
        if (stop >= s.size() || s[stop] == '{') {  // a uniform block, or no end
            i = stop;
            continue;
        }
        // Declarators split at depth-0 commas: the first carries the type.
        std::string type;
        size_t from = end;
        for (size_t k = end; k <= stop; ++k) {
            if (k < stop && s[k] == '(') ++parens;
            if (k < stop && s[k] == ')') --parens;
            if (k < stop && !(parens == 0 && s[k] == ',')) continue;
            std::string_view decl(s.data() + from, k - from);
            size_t eq = decl.find('=');
            std::string_view left = decl.substr(0, eq);
            const bool array = left.find('[') != std::string_view::npos;
            // The words before '=' (and an array's size): [precision] TYPE NAME, or NAME after a comma.
            left = left.substr(0, left.find('['));
            const std::vector<std::string_view> words = glslWords(left);
            if (type.empty() && words.size() >= 2) type = std::string(words[words.size() - 2]);
            if (eq != std::string_view::npos && !words.empty()) {
                UniformInitializer u;
                u.name = std::string(words.back());
                u.type = type;
                size_t valueAt = from + eq + 1;
                while (valueAt < k && isBlank(s[valueAt])) ++valueAt;
                Place p = placeOf(valueAt);
                u.line = p.line;
                u.col = p.col;
                if (!array && readValue(type, decl.substr(eq + 1), u.values)) out.values.push_back(std::move(u));
                else out.unreadable.push_back(std::move(u));
                for (size_t b = from + eq; b < k; ++b)
                    if (s[b] != '\n') s[b] = ' ';
            }
            from = k + 1;
        }
        i = stop + 1;
    }
    return out;
}

}  // namespace glimmer
