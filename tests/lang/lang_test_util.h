// Helpers shared by the language tests: a parse in one call, and compact
// renderings of commands and diagnostics so that expectations read like the
// script they describe.
#pragma once
#include <charconv>
#include <string>
#include <vector>

#include "lang/diagnostics.h"
#include "lang/parser.h"

namespace glimmer::test {

struct Parsed {
    Script script;
    Diagnostics diags;
};

inline Parsed parse(const std::string& text, const std::string& file = "t.glib") {
    Parsed p;
    p.script = parseScript(file, text, p.diags);
    return p;
}

inline std::string num(double v) {
    char buf[64];
    auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, ptr);
}

// Numbers as their value, Words quoted, groups with their brackets.
inline std::string dump(const Arg& a) {
    switch (a.kind) {
        case Arg::Kind::Number: return num(a.number);
        case Arg::Kind::Word: return "'" + a.text + "'";
        default: break;
    }
    std::string open = a.kind == Arg::Kind::Range ? "<" : a.kind == Arg::Kind::Color ? "{" : "[";
    std::string close = a.kind == Arg::Kind::Range ? ">" : a.kind == Arg::Kind::Color ? "}" : "]";
    std::string s = open;
    for (size_t i = 0; i < a.items.size(); ++i) s += (i ? " " : "") + dump(a.items[i]);
    return s + close;
}

// "Canonical@line:col args..."
inline std::string dump(const Command& c) {
    std::string s = std::string(commandName(c.kind)) + "@" + std::to_string(c.loc.line) + ":" +
                    std::to_string(c.loc.col);
    for (const Arg& a : c.args) s += " " + dump(a);
    return s;
}

inline std::vector<std::string> dump(const Script& s) {
    std::vector<std::string> out;
    for (const Command& c : s.commands) out.push_back(dump(c));
    return out;
}

// "line:col: severity: message"
inline std::vector<std::string> messages(const Diagnostics& d) {
    std::vector<std::string> out;
    for (const Diagnostic& x : d.all())
        out.push_back(std::to_string(x.loc.line) + ":" + std::to_string(x.loc.col) + ": " +
                      severityName(x.severity) + ": " + x.message);
    return out;
}

inline std::string loc(const SourceLoc& l) { return std::to_string(l.line) + ":" + std::to_string(l.col); }

}  // namespace glimmer::test
