// Driver info logs parsed by hand, in one pass over each line: std::regex
// recursed once per character and overflowed the stack on a 30,000-character
// log line. The forms (Mesa, with glcpp's "preprocessor error"; NVIDIA):
//   Mesa:   ws* D+ ':' LINE '(' COL ')' ':' ws* ("preprocessor" ws+)? (error|warning) ws* ':'? ws* MESSAGE
//   NVIDIA: ws* D+ '(' LINE ')' ws* ':' ws* (error|warning) ws+ WORD ':' ws* MESSAGE
#include <climits>
#include <cstring>

#include "gl/shader_build.h"
#include "shader/missing_semicolon.h"
#include "shader/glsl_scan.h"

namespace glimmer {
namespace {

struct Scan {
    const std::string& s;
    size_t i = 0;

    static bool space(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r' || c == '\n'; }
    static bool word(char c) { return isGlslWordChar(c); }
    size_t spaces() {
        size_t n = 0;
        while (i < s.size() && space(s[i])) ++i, ++n;
        return n;
    }
    bool ch(char c) {
        if (i < s.size() && s[i] == c) {
            ++i;
            return true;
        }
        return false;
    }
    bool lit(const char* w) {
        size_t n = std::strlen(w);
        if (s.compare(i, n, w) != 0) return false;
        i += n;
        return true;
    }
    // One or more digits, the value clamped to INT_MAX (a log's line number
    // must never throw, as std::stoi would).
    bool number(int& v) {
        size_t start = i;
        long long x = 0;
        while (i < s.size() && s[i] >= '0' && s[i] <= '9') {
            x = x * 10 + (s[i++] - '0');
            if (x > INT_MAX) x = INT_MAX;
        }
        v = int(x);
        return i > start;
    }
    bool severity(Severity& sev) {
        if (lit("error")) sev = Severity::Error;
        else if (lit("warning")) sev = Severity::Warning;
        else return false;
        return true;
    }
    std::string rest() const { return s.substr(i); }
};

bool parseMesa(const std::string& line, int& ln, int& col, Severity& sev, std::string& msg) {
    Scan c{line};
    int ignored = 0;
    c.spaces();
    if (!c.number(ignored) || !c.ch(':') || !c.number(ln) || !c.ch('(') || !c.number(col) || !c.ch(')') || !c.ch(':'))
        return false;
    c.spaces();
    size_t before = c.i;
    if (c.lit("preprocessor") && c.spaces() == 0) c.i = before;  // "preprocessor" needs a space after it
    if (!c.severity(sev)) return false;
    c.spaces();
    c.ch(':');
    c.spaces();
    msg = c.rest();
    return true;
}

bool parseNvidia(const std::string& line, int& ln, Severity& sev, std::string& msg) {
    Scan c{line};
    int ignored = 0;
    c.spaces();
    if (!c.number(ignored) || !c.ch('(') || !c.number(ln) || !c.ch(')')) return false;
    c.spaces();
    if (!c.ch(':')) return false;
    c.spaces();
    if (!c.severity(sev) || c.spaces() == 0) return false;
    size_t start = c.i;
    while (c.i < line.size() && Scan::word(line[c.i])) ++c.i;
    if (c.i == start || !c.ch(':')) return false;
    c.spaces();
    msg = c.rest();
    return true;
}

}  // namespace

void mapCompilerLog(const std::string& log, const PreparedSource& src, const std::string& file,
                    const std::string& fallbackFile, SourceLoc fallback, Severity defaultSeverity,
                    Diagnostics& diags) {
    std::string unmatched;
    size_t start = 0;
    while (start < log.size()) {
        size_t nl = log.find('\n', start);
        if (nl == std::string::npos) nl = log.size();
        std::string line = log.substr(start, nl - start);
        start = nl + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        Diagnostic d;
        d.file = file;
        d.fromDriver = true;
        int ln = 0, col = 0;
        if (parseMesa(line, ln, col, d.severity, d.message)) {
            d.loc = {src.originalLine(ln), col};
        } else if (parseNvidia(line, ln, d.severity, d.message)) {
            d.loc = {src.originalLine(ln), 0};
        } else {
            if (line.find_first_not_of(" \t") != std::string::npos) unmatched += (unmatched.empty() ? "" : "\n") + line;
            continue;
        }
        // A ';' missing at the end of the line before: marked there, the
        // driver's place a note (shader/missing_semicolon.h). Found in the
        // compiled text, then mapped back past the lines Glimmer inserted.
        if (auto missing = missingSemicolonAt(d.message, src.text, ln)) {
            const SourceLoc next = d.loc;
            d.loc = {src.originalLine(missing->line), missing->col};
            diags.add(d);
            diags.add({Severity::Note, file, next, "the next statement starts here", false});  // ours, never folded away
            continue;
        }
        diags.add(d);
    }
    if (!unmatched.empty()) diags.add({defaultSeverity, fallbackFile, fallback, unmatched, true});
}

}  // namespace glimmer
