#include "shader/uninitialized_globals.h"
#include "shader/glsl_scan.h"

#include <cctype>
#include <set>
#include <vector>

namespace glimmer {
namespace {

// The text with comments and preprocessor lines blanked (newlines kept), so
// offsets and line numbers stay those of the original.
std::string codeOnly(const std::string& t) {
    std::string s = blankComments(t);
    for (size_t i = 0; i < s.size(); ++i)
        if (s[i] == '#' && (i == 0 || s[i - 1] == '\n'))
            while (i < s.size() && s[i] != '\n') s[i++] = ' ';
    return s;
}

// glslWords, as strings (the callers look them up in sets of strings).
std::vector<std::string> words(const std::string& s) {
    const std::vector<std::string_view> found = glslWords(s);
    return {found.begin(), found.end()};
}

bool hasWord(const std::string& s, const std::string& w) {
    for (const auto& x : words(s))
        if (x == w) return true;
    return false;
}

struct Function {
    std::string name;
    size_t open = 0, close = 0;  // offsets of its body's braces
};

int lineAt(const std::string& s, size_t offset) {
    int line = 1;
    for (size_t i = 0; i < offset && i < s.size(); ++i) line += s[i] == '\n';
    return line;
}

// Whether `stmt` (one statement of main, at its top level) starts by
// assigning `name` (`name = ...`, `name.xy = ...`, `name[i] = ...`).
bool assigns(const std::string& stmt, const std::string& name) {
    size_t i = stmt.find_first_not_of(" \t\r\n");
    if (i == std::string::npos || stmt.compare(i, name.size(), name) != 0) return false;
    i += name.size();
    if (i < stmt.size() && isGlslWordChar(stmt[i])) return false;
    while (i < stmt.size() && (stmt[i] == ' ' || stmt[i] == '\t' || stmt[i] == '.' || isGlslWordChar(stmt[i]))) ++i;
    if (i < stmt.size() && stmt[i] == '[') {
        size_t close = stmt.find(']', i);
        if (close == std::string::npos) return false;
        i = stmt.find_first_not_of(" \t", close + 1);
    }
    return i != std::string::npos && i + 1 < stmt.size() && stmt[i] == '=' && stmt[i + 1] != '=';
}

}  // namespace

int globalSetByMainFirst(const std::string& text, const std::string& name, int warningLine) {
    const std::string s = codeOnly(text);
    // File scope: function bodies and the declarations between them.
    std::vector<Function> functions;
    bool isGlobal = false;
    size_t stmtStart = 0;
    int depth = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        char c = s[i];
        if (c == '{') {
            if (depth++ == 0) {
                std::string head = s.substr(stmtStart, i - stmtStart);
                size_t paren = head.find('(');
                if (paren != std::string::npos) {
                    std::vector<std::string> w = words(head.substr(0, paren));
                    if (!w.empty()) functions.push_back({w.back(), i, 0});
                }
            }
        } else if (c == '}') {
            if (--depth == 0) {
                if (!functions.empty() && functions.back().close == 0) functions.back().close = i;
                stmtStart = i + 1;
            }
            if (depth < 0) return 0;
        } else if (c == ';' && depth == 0) {
            std::string decl = s.substr(stmtStart, i - stmtStart);
            std::vector<std::string> w = words(decl);
            static const std::set<std::string> notPlain = {"uniform", "in", "out", "inout", "attribute", "varying",
                                                           "const", "layout", "buffer", "shared", "struct"};
            if (!w.empty() && !notPlain.count(w[0]) && decl.find('(') == std::string::npos && hasWord(decl, name))
                isGlobal = true;
            stmtStart = i + 1;
        }
    }
    if (!isGlobal) return 0;
    const Function* main = nullptr;
    const Function* reader = nullptr;
    for (const auto& f : functions) {
        if (f.name == "main") main = &f;
        if (f.close && lineAt(s, f.open) <= warningLine && warningLine <= lineAt(s, f.close)) reader = &f;
    }
    if (!main || !main->close || !reader || reader == main) return 0;
    std::set<std::string> defined;
    for (const auto& f : functions)
        if (f.name != "main") defined.insert(f.name);
    // main's statements at its top level, in order: the first that sets the
    // global must come before the first that calls a function of the shader.
    int inner = 0, parens = 0;
    size_t start = main->open + 1;
    for (size_t i = main->open + 1; i < main->close; ++i) {
        char c = s[i];
        if (c == '(') ++parens;
        else if (c == ')') --parens;
        else if (c == '{') ++inner;
        else if (c == '}') --inner;
        bool ends = (c == ';' && inner == 0 && parens == 0) || (c == '}' && inner == 0);
        if (!ends) continue;
        std::string stmt = s.substr(start, i + 1 - start);
        if (inner == 0 && c == ';' && assigns(stmt, name)) {
            // Its right-hand side must not call one either.
            bool calls = false;
            for (const auto& w : words(stmt)) calls = calls || defined.count(w);
            if (!calls) return lineAt(s, start + stmt.find_first_not_of(" \t\r\n"));
        }
        for (const auto& w : words(stmt))
            if (defined.count(w) || w == name) return 0;  // a call first, or a read of it
        start = i + 1;
    }
    return 0;
}

}  // namespace glimmer
