#include "shader/missing_semicolon.h"

#include <vector>

namespace glimmer {

namespace {

bool saysSemicolonExpected(std::string_view m) {
    const size_t expecting = m.find("expecting");
    if (expecting == std::string_view::npos) return false;
    const std::string_view rest = m.substr(expecting);
    return rest.find("';'") != std::string_view::npos || rest.find("SEMICOLON") != std::string_view::npos;
}

std::vector<std::string_view> linesOf(std::string_view text) {
    std::vector<std::string_view> out;
    for (size_t at = 0; at <= text.size();) {
        size_t nl = text.find('\n', at);
        if (nl == std::string_view::npos) nl = text.size();
        out.push_back(text.substr(at, nl - at));
        at = nl + 1;
    }
    return out;
}

// The line without a `//` comment and trailing blanks (GLSL has no strings
// for a "//" to hide in).
std::string_view codeOf(std::string_view l) {
    if (size_t c = l.find("//"); c != std::string_view::npos) l = l.substr(0, c);
    while (!l.empty() && (l.back() == ' ' || l.back() == '\t' || l.back() == '\r')) l.remove_suffix(1);
    return l;
}

}  // namespace

std::optional<SourceLoc> missingSemicolonAt(std::string_view message, std::string_view text, int line) {
    if (!saysSemicolonExpected(message) || line < 2) return std::nullopt;
    const auto lines = linesOf(text);
    for (int at = line - 1; at >= 1 && size_t(at) <= lines.size(); --at) {
        const std::string_view code = codeOf(lines[size_t(at - 1)]);
        const size_t first = code.find_first_not_of(" \t");
        if (first == std::string_view::npos) continue;  // blank, or a comment alone
        if (code[first] == '#') return std::nullopt;     // a preprocessor line ends no statement
        const char last = code.back();
        if (last == ';' || last == '{' || last == '}' || last == ',' || last == '(') return std::nullopt;
        return SourceLoc{at, int(code.size()) + 1};
    }
    return std::nullopt;
}

}  // namespace glimmer
