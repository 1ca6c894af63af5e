// What a watch names (shader/watch_rewrite.h): FILE:LINE:EXPR parsed, and
// whether the expression can go into a shader as one expression. The
// expression is at most kMaxWatchExpression characters the user typed, read
// here byte by byte: it is checked before any shader text is touched.
#include <algorithm>

#include "shader/watch_rewrite.h"

namespace glimmer {
namespace {

constexpr int kMaxWatchLine = 1000000;

}  // namespace

std::string watchExpressionProblem(std::string_view e) {
    size_t a = 0, b = e.size();
    while (a < b && (e[a] == ' ' || e[a] == '\t')) ++a;
    while (b > a && (e[b - 1] == ' ' || e[b - 1] == '\t')) --b;
    if (a == b) return "the expression to watch is empty";
    if (e.size() > kMaxWatchExpression)
        return "the expression is " + std::to_string(e.size()) + " characters long; a watch takes at most " +
               std::to_string(kMaxWatchExpression);
    std::string open;
    for (size_t i = 0; i < e.size(); ++i) {
        char c = e[i];
        if (c == ';' || c == '{' || c == '}' || c == '#' || c == '\n' || c == '\r' ||
            (c == '/' && i + 1 < e.size() && (e[i + 1] == '/' || e[i + 1] == '*')))
            return "a watch takes one expression, and '" +
                   (c == '\n' ? std::string("\\n") : c == '\r' ? std::string("\\r") : std::string(e.substr(i, c == '/' ? 2 : 1))) +
                   "' cannot be in one";
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e)
            return "the expression holds a character that is not GLSL (only printable ASCII is)";
        if (c == '(' || c == '[') open += c;
        if (c == ')' || c == ']') {
            if (open.empty() || open.back() != (c == ')' ? '(' : '['))
                return std::string("the expression's brackets do not balance (a '") + c + "' with nothing open)";
            open.pop_back();
        }
    }
    if (!open.empty()) return std::string("the expression's brackets do not balance (a '") + open.back() + "' never closes)";
    return {};
}

bool parseWatchSpec(std::string_view text, WatchSpec& out, std::string& why) {
    // The file is everything before the first ":DIGITS:" or ":DIGITS ":
    // a file name may hold colons of its own.
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] != ':' || i == 0) continue;
        size_t d = i + 1;
        long long n = 0;
        while (d < text.size() && text[d] >= '0' && text[d] <= '9') n = std::min<long long>(n * 10 + (text[d++] - '0'), kMaxWatchLine + 1);
        if (d == i + 1 || d >= text.size() || (text[d] != ':' && text[d] != ' ')) continue;
        out.file = std::string(text.substr(0, i));
        if (n < 1 || n > kMaxWatchLine) {
            why = "the line number " + std::string(text.substr(i + 1, d - i - 1)) + " is not a line of a shader";
            return false;
        }
        out.line = int(n);
        std::string_view e = text.substr(d + 1);
        while (!e.empty() && e.front() == ' ') e.remove_prefix(1);
        while (!e.empty() && e.back() == ' ') e.remove_suffix(1);
        out.expression = std::string(e);
        why = watchExpressionProblem(e);
        return why.empty();
    }
    why = "'" + std::string(text.substr(0, 80)) + "' is not FILE:LINE:EXPRESSION (for example bloom.frag:12:rgbblur)";
    return false;
}

}  // namespace glimmer
