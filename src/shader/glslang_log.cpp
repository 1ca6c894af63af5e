#include "shader/glslang_log.h"
#include "shader/missing_semicolon.h"

#include <cctype>
#include <climits>
#include <utility>
#include <vector>

#include "shader/glsl_lexer.h"
#include "shader/glsl_scan.h"

namespace glimmer {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// "0:12: rest" -> 12 and "rest"; false when the line has no such location.
bool splitLocation(std::string_view s, int& line, std::string_view& rest) {
    size_t i = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    if (i == 0 || i >= s.size() || s[i] != ':') return false;
    size_t j = ++i;
    long long v = 0;
    while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) {
        v = v * 10 + (s[j++] - '0');
        if (v > INT_MAX) v = INT_MAX;
    }
    if (j == i || j >= s.size() || s[j] != ':') return false;
    line = int(v);
    rest = trim(s.substr(j + 1));
    return true;
}

// "'tok' : message" -> "tok" ("" when the message quotes nothing first).
std::string_view quotedToken(std::string_view msg) {
    if (msg.empty() || msg.front() != '\'') return {};
    size_t end = msg.find("' :", 1);
    return end == std::string_view::npos ? std::string_view{} : msg.substr(1, end - 1);
}

// glslang's "'tok' :  message" as Glimmer writes messages: "'tok': message",
// and "message" alone where it quotes nothing ('').
std::string tidy(std::string_view msg) {
    std::string_view token = quotedToken(msg);
    if (msg.empty() || msg.front() != '\'' || msg.find("' :", 1) != token.size() + 1) return std::string(msg);
    std::string_view rest = trim(msg.substr(token.size() + 4));
    if (token.empty()) return std::string(rest);
    return "'" + std::string(token) + "': " + std::string(rest);
}

// "syntax error, unexpected STAR": the character glslang's token name means,
// so the caret stands on it ("" for a token of no fixed spelling).
std::string_view unexpectedToken(std::string_view msg) {
    static constexpr std::pair<std::string_view, std::string_view> kSpellings[] = {
        {"STAR", "*"},        {"PLUS", "+"},          {"DASH", "-"},          {"SLASH", "/"},
        {"PERCENT", "%"},     {"SEMICOLON", ";"},     {"COMMA", ","},         {"COLON", ":"},
        {"DOT", "."},         {"EQUAL", "="},         {"LEFT_PAREN", "("},    {"RIGHT_PAREN", ")"},
        {"LEFT_BRACE", "{"},  {"RIGHT_BRACE", "}"},   {"LEFT_BRACKET", "["},  {"RIGHT_BRACKET", "]"},
        {"BANG", "!"},        {"TILDE", "~"},         {"QUESTION", "?"},      {"CARET", "^"},
        {"AMPERSAND", "&"},   {"VERTICAL_BAR", "|"},  {"LEFT_ANGLE", "<"},    {"RIGHT_ANGLE", ">"},
    };
    constexpr std::string_view key = "unexpected ";
    size_t at = msg.find(key);
    if (at == std::string_view::npos) return {};
    std::string_view name = msg.substr(at + key.size());
    name = name.substr(0, name.find_first_of(", "));
    for (const auto& [n, spelled] : kSpellings)
        if (n == name) return spelled;
    return {};
}

}  // namespace

// The line's code tokens, a directive's own words among them (an error in
// `#extension foo : require` names foo), in order, offsets into the line.
// The line is lexed alone: a log names a line, and lexing the whole shader
// for each of its messages would cost the shader's size each time.
int columnOf(std::string_view text, int line, std::string_view token) {
    const std::string_view l = lineOf(text, line);
    if (token.empty()) return 0;
    std::vector<GlslToken> code;
    for (const GlslToken& t : lexGlsl(l)) {
        if (isGlslCode(t.kind)) code.push_back(t);
        if (t.kind != GlslTokenKind::Directive) continue;
        for (GlslToken w : directiveTokens(tokenText(l, t))) {
            w.begin += t.begin;
            w.end += t.begin;
            code.push_back(w);
        }
    }
    // The first run of whole tokens spelled `token` ("<=" holds no '=', "uKd" is not in "uKdColor").
    for (size_t k = 0; k < code.size(); ++k) {
        const size_t at = code[k].begin, end = at + token.size();
        if (l.compare(at, token.size(), token) != 0) continue;
        for (size_t j = k; j < code.size() && code[j].end <= end; ++j)
            if (code[j].end == end) return int(at) + 1;
    }
    return 0;
}

int mapGlslangLog(std::string_view log, const GlslangLogContext& cx, Diagnostics& diags) {
    int errors = 0;
    size_t at = 0;
    while (at < log.size()) {
        size_t end = log.find('\n', at);
        if (end == std::string_view::npos) end = log.size();
        std::string_view l = trim(log.substr(at, end - at));
        at = end + 1;
        Severity sev;
        if (l.rfind("ERROR:", 0) == 0) sev = Severity::Error, l.remove_prefix(6);
        else if (l.rfind("WARNING:", 0) == 0) sev = Severity::Warning, l.remove_prefix(8);
        else if (l.rfind("NOTE:", 0) == 0) sev = Severity::Note, l.remove_prefix(5);
        else if (l.empty()) continue;
        else sev = Severity::Error;  // a line of no known form: kept whole
        l = trim(l);
        // The count glslang ends with says nothing the lines above did not.
        if (l.find("compilation errors.") != std::string_view::npos && l.find("No code generated") != std::string_view::npos)
            continue;
        if (l.find("compilation terminated") != std::string_view::npos) continue;
        int line = 0;
        std::string_view msg = l;
        SourceLoc loc;
        if (splitLocation(l, line, msg)) {
            loc.line = line;
            std::string_view token = quotedToken(msg);
            if (token.empty()) token = unexpectedToken(msg);
            int col = columnOf(cx.userText, line, token);
            if (!col && cx.renames) {
                auto r = cx.renames->find(std::string(token));
                if (r != cx.renames->end()) col = columnOf(cx.userText, line, r->second);
            }
            if (!col) {  // the line's first character
                std::string_view u = lineOf(cx.userText, line);
                size_t p = u.find_first_not_of(" \t");
                col = p == std::string_view::npos ? 1 : int(p) + 1;
            }
            loc.col = col;
        }
        std::string text = cx.prefix + tidy(msg);
        // A compatibility built-in the translation has no stand-in for is
        // undeclared in core GLSL; say why, not only that.
        std::string_view token = quotedToken(msg);
        if (token.rfind("gl_", 0) == 0 && msg.find("undeclared identifier") != std::string_view::npos)
            text += " (a compatibility-profile built-in that WebGL 2 has no stand-in for)";
        // A ';' missing at the end of the line before: marked there, the
        // next statement's start a note (shader/missing_semicolon.h).
        const auto missing = loc.line ? missingSemicolonAt(msg, cx.userText, loc.line) : std::nullopt;
        diags.add({sev, cx.file, missing ? *missing : loc, std::move(text)});
        if (missing) diags.note(cx.file, loc, "the next statement starts here");
        errors += sev == Severity::Error;
    }
    return errors;
}

}  // namespace glimmer
