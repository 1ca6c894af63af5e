// The watch's rewrite of a shader (shader/watch_rewrite.h). Held by
// test_cli's CliWatch.IntsUintsAndBoolsAreWatchedAndSaidAsWhatTheyAre to
// every overload of the capture, each type said with its components (issue
// 40: a scalar uint's count was 0 and no test watched one).
#include "shader/watch_rewrite.h"

#include <algorithm>
#include <vector>

#include "shader/glsl_lexer.h"
#include "shader/glsl_scan.h"

namespace glimmer {
namespace {

constexpr std::string_view kWatchedMain = "glimmer_watched_main";
constexpr size_t kNone = std::string_view::npos;

// The shader's code tokens (no blanks, comments or directives) and the
// questions the passes below ask of them.
struct Code {
    std::string_view text;
    std::vector<GlslToken> tokens;
    explicit Code(std::string_view source) : text(source), tokens(glslCodeTokens(source)) {}
    size_t size() const { return tokens.size(); }
    std::string_view at(size_t k) const { return tokenText(text, tokens[k]); }
    bool word(size_t k, std::string_view w) const { return isWordToken(text, tokens, k, w); }
    bool punct(size_t k, std::string_view p) const { return isPunctToken(text, tokens, k, p); }
    // The word token `k` is, "" when it is no word.
    std::string_view wordAt(size_t k) const { return k < size() && tokens[k].kind == GlslTokenKind::Word ? at(k) : ""; }
};

// A function's body, as token indices: where its declaration starts, its
// '{' and the matching '}' (kNone: never closed).
struct Body {
    size_t decl, open, close;
};

// The bodies of the functions defined at file scope: a top-level '{' right
// after a ')'. A struct's or block's braces are not bodies.
std::vector<Body> functionBodies(const Code& code) {
    std::vector<Body> bodies;
    size_t decl = 0;
    int depth = 0;
    for (size_t k = 0; k < code.size(); ++k) {
        if (code.punct(k, "{")) {
            if (depth == 0 && k > 0 && code.punct(k - 1, ")")) {
                int d = 1;
                size_t j = k + 1;
                for (; j < code.size() && d > 0; ++j) d += code.punct(j, "{") ? 1 : code.punct(j, "}") ? -1 : 0;
                const size_t close = d == 0 ? j - 1 : kNone;
                bodies.push_back({decl, k, close});
                if (close == kNone) break;
                k = close;
                decl = close + 1;
                continue;
            }
            ++depth;
        } else if (code.punct(k, "}")) {
            depth = std::max(0, depth - 1);
            if (depth == 0) decl = k + 1;
        } else if (code.punct(k, ";") && depth == 0) {
            decl = k + 1;
        }
    }
    return bodies;
}

// `bodies` are in the order of the text and never overlap: the one that
// could hold token `k` is the last that opens before it (a binary search;
// issue 38: a scan of every body for every character watched a shader of
// 80,000 small functions in 209 s).
bool inBody(const std::vector<Body>& bodies, size_t k) {
    auto after = std::upper_bound(bodies.begin(), bodies.end(), k, [](size_t a, const Body& b) { return a <= b.open; });
    if (after == bodies.begin()) return false;
    const Body& b = *(after - 1);
    return k > b.open && k < b.close;
}

// Where on the watched line the capture goes. The statement that holds the
// line's last token is found by a pass over its function's body from the
// top: statements end at a ';' outside brackets, blocks open and close at
// braces, a case label ends at its ':', and the body of an if / for /
// while / else / do without braces starts after its header.
struct Placement {
    bool ok = false;
    std::string error;
    std::vector<GlslEdit> edits;
};
Placement placeCapture(const Code& code, const Body& body, size_t last, const std::string& capture) {
    size_t stmtStart = body.open + 1;
    bool controlBody = false, pendingControl = false, inHeader = false;
    int paren = 0, depth = 0;
    // A do's `while (...)` is the end of its statement, not a loop header
    // with a body after it (issue 38: `do x += 0.5; while (x < 0.);` was
    // watched as `while (x < 0.) { ; capture }`). doDepths: the brace depth
    // of each do whose tail is still to come; afterDoBody: its body just
    // ended, so a `while` now is that tail.
    std::vector<int> doDepths;
    bool afterDoBody = false;
    // The statement from `first` to the ';' at `semicolon` watched: after
    // it, or before it when it is a jump; braced when it is a lone body.
    auto watchStatement = [&](size_t first, size_t semicolon, bool lone, std::vector<GlslEdit>& edits) {
        const size_t at = code.tokens[first].begin, after = code.tokens[semicolon].end;
        const std::string_view w = code.wordAt(first);
        const bool jump = w == "return" || w == "discard" || w == "break" || w == "continue";
        if (lone) edits.push_back({at, 0, "{ "});
        if (jump) edits.push_back({at, 0, capture + " "});
        else edits.push_back({after, 0, capture});
        if (lone) edits.push_back({after, 0, " }"});
    };
    // `if (a) b = 1.; else b = 2.;` on the watched line: whichever branch
    // runs, the line ran, so each branch that ends on the line before an
    // `else` is watched too (else the pixels that took the first would say
    // the line never ran there).
    const int watchedLine = code.tokens[last].line;
    std::vector<GlslEdit> earlierBranches;
    const size_t end = std::min(body.close, code.size());
    for (size_t k = body.open + 1; k < end; ++k) {
        const GlslToken& t = code.tokens[k];
        if (t.kind == GlslTokenKind::Word) {
            if (paren != 0) continue;
            const std::string_view w = code.at(k);
            const bool doTail = afterDoBody && w == "while";
            afterDoBody = false;
            if (doTail) doDepths.pop_back();
            else if (w == "if" || w == "for" || w == "while" || w == "switch") pendingControl = true;
            if (w == "else" || w == "do") stmtStart = k + 1, controlBody = true;
            if (w == "do") doDepths.push_back(depth);
            continue;
        }
        if (code.punct(k, "(") || code.punct(k, "[")) {
            if (paren == 0 && pendingControl && code.punct(k, "(")) inHeader = true, pendingControl = false;
            ++paren;
        } else if (code.punct(k, ")") || code.punct(k, "]")) {
            paren = std::max(0, paren - 1);
            if (paren == 0 && inHeader) inHeader = false, stmtStart = k + 1, controlBody = true;
        } else if (paren == 0 && (code.punct(k, "{") || code.punct(k, "}"))) {
            const bool opens = code.punct(k, "{");
            if (k >= last) {
                // A block opens on the line: the value at its start; a block
                // closes: the value at its end (each pass of a loop).
                return {true, "", {{opens ? t.end : t.begin, 0, capture}}};
            }
            depth = opens ? depth + 1 : std::max(0, depth - 1);
            afterDoBody = !opens && !doDepths.empty() && depth == doDepths.back();
            if (opens || !code.word(k + 1, "else")) earlierBranches.clear();
            else if (t.line == watchedLine) earlierBranches.push_back({t.begin, 0, capture});
            stmtStart = k + 1, controlBody = false, pendingControl = false;
        } else if (paren == 0 && code.punct(k, ":") && (code.word(stmtStart, "case") || code.word(stmtStart, "default"))) {
            // A label is no statement: nothing runs at it.
            if (k >= last)
                return {false, "the line ends with a case label, which runs nothing: watch the line of a statement after it", {}};
            stmtStart = k + 1;
        } else if (paren == 0 && code.punct(k, ";")) {
            if (k >= last) {
                // A jump is watched just before it leaves; the lone body of an
                // if or a loop gets braces, so the capture stays inside it.
                std::vector<GlslEdit> edits = earlierBranches;
                watchStatement(stmtStart, k, controlBody, edits);
                return {true, "", edits};
            }
            if (!code.word(k + 1, "else")) earlierBranches.clear();
            else if (t.line == watchedLine) watchStatement(stmtStart, k, controlBody, earlierBranches);
            afterDoBody = !doDepths.empty() && depth == doDepths.back() && controlBody;
            stmtStart = k + 1, controlBody = false, pendingControl = false;
        }
    }
    return {false, "the statement on this line never ends (no ';' or brace before the function's end)", {}};
}

// Every `old` word of the code becomes `now`.
void renameWord(const Code& code, std::string_view old, std::string_view now, std::vector<GlslEdit>& edits, bool& found) {
    for (size_t k = 0; k < code.size(); ++k) {
        if (!code.word(k, old)) continue;
        edits.push_back({code.tokens[k].begin, old.size(), std::string(now)});
        found = true;
    }
}

// The fragment stage's own outputs become plain globals: `out` (and the
// `layout(...)` before it) at file scope is blanked, so the declarations
// stay where they are and keep their columns.
void demoteOutputs(const Code& code, const std::vector<Body>& bodies, std::vector<GlslEdit>& edits) {
    int paren = 0, depth = 0;
    size_t layoutAt = kNone, layoutEnd = 0;  // offsets of `layout` and past the ')' after it
    for (size_t k = 0; k < code.size(); ++k) {
        if (inBody(bodies, k)) continue;
        const GlslToken& t = code.tokens[k];
        if (code.punct(k, "(")) ++paren;
        else if (code.punct(k, ")")) paren = std::max(0, paren - 1), layoutEnd = t.end;
        else if (code.punct(k, "{")) ++depth;
        else if (code.punct(k, "}")) depth = std::max(0, depth - 1);
        else if (code.punct(k, ";")) layoutAt = kNone;
        if (t.kind != GlslTokenKind::Word || paren || depth) continue;
        if (code.at(k) == "layout") layoutAt = t.begin;
        if (code.at(k) == "out") {
            edits.push_back({t.begin, 3, "   "});
            if (layoutAt != kNone && layoutEnd > layoutAt)
                edits.push_back({layoutAt, layoutEnd - layoutAt, std::string(layoutEnd - layoutAt, ' ')});
            layoutAt = kNone;
        }
    }
}

struct Flavour {
    bool modern;   // GLSL 3.30 or ES 3.00: outputs with layout locations
    bool outs;     // GLSL 1.30 on: `in` / `out` rather than varying / gl_FragData
    bool uints;    // has uint
    std::string hp;  // "highp " where precision qualifiers exist
};
Flavour flavourOf(std::string_view source) {
    GlslVersion v = glslVersionOf(source);
    bool es = v.profile == "es";
    Flavour f;
    f.modern = es || v.number >= 330;
    f.outs = es || v.number >= 130;
    f.uints = f.outs;
    f.hp = f.outs ? "highp " : "";
    return f;
}

// The globals and overloads the capture calls, on one line: the value widened
// to a vec4, its component count and its kind.
std::string helpers(const Flavour& f) {
    std::string h = f.hp + "vec4 glimmer_watch_v; " + f.hp + "float glimmer_watch_n; " + f.hp +
                    "float glimmer_watch_k; void glimmer_watch_put(" + f.hp +
                    "vec4 v, float n, float k) { glimmer_watch_v = v; glimmer_watch_n = n; glimmer_watch_k = k; } ";
    struct Overload {
        const char* type;
        const char* widen;
        int n, kind;
    };
    static const Overload kOverloads[] = {
        {"float", "vec4(v, 0., 0., 0.)", 1, 0},        {"vec2", "vec4(v, 0., 0.)", 2, 0},
        {"vec3", "vec4(v, 0.)", 3, 0},                 {"vec4", "v", 4, 0},
        {"int", "vec4(float(v), 0., 0., 0.)", 1, 1},   {"ivec2", "vec4(vec2(v), 0., 0.)", 2, 1},
        {"ivec3", "vec4(vec3(v), 0.)", 3, 1},          {"ivec4", "vec4(v)", 4, 1},
        {"uint", "vec4(float(v), 0., 0., 0.)", 1, 2},  {"uvec2", "vec4(vec2(v), 0., 0.)", 2, 2},
        {"uvec3", "vec4(vec3(v), 0.)", 3, 2},          {"uvec4", "vec4(v)", 4, 2},
        {"bool", "vec4(v ? 1. : 0., 0., 0., 0.)", 1, 3}, {"bvec2", "vec4(vec2(v), 0., 0.)", 2, 3},
        {"bvec3", "vec4(vec3(v), 0.)", 3, 3},          {"bvec4", "vec4(v)", 4, 3},
    };
    for (const Overload& o : kOverloads) {
        if (o.kind == 2 && !f.uints) continue;
        h += "void " + std::string(kWatchStore) + "(" + o.type + " v) { glimmer_watch_put(" + o.widen + ", " +
             std::to_string(o.n) + ".," + std::to_string(o.kind) + ".); } ";
    }
    return h;
}

// Renames the shader's main (its definition and any prototype) to
// kWatchedMain, so an added main can call it; false when it has none.
bool renameMain(const Code& code, const std::vector<Body>& bodies, std::vector<GlslEdit>& edits) {
    bool found = false;
    for (size_t k = 0; k < code.size(); ++k)
        if (code.word(k, "main") && !inBody(bodies, k) && code.punct(k + 1, "("))
            edits.push_back({code.tokens[k].begin, 4, std::string(kWatchedMain)}), found = true;
    return found;
}

// What the fragment stage wrote becomes globals of the same names (renamed
// built-ins, demoted `out`s): the added main writes the watch's two outputs
// instead. Returns the declarations the renamed built-ins need.
std::string outputsToGlobals(const Code& code, const std::vector<Body>& bodies, const Flavour& f,
                             std::vector<GlslEdit>& edits) {
    bool color = false, data = false;
    renameWord(code, "gl_FragColor", "glimmer_watch_FragColor", edits, color);
    renameWord(code, "gl_FragData", "glimmer_watch_FragData", edits, data);
    if (f.outs) demoteOutputs(code, bodies, edits);
    return std::string(color ? "vec4 glimmer_watch_FragColor; " : "") + (data ? "vec4 glimmer_watch_FragData[8]; " : "");
}

// Where declarations may go ahead of every function: the start of the first
// function's declaration, on its own line (so no line moves).
size_t beforeFunctions(const Code& code, const std::vector<Body>& bodies) { return code.tokens[bodies.front().decl].begin; }

std::string lineEnding(std::string_view text) { return !text.empty() && text.back() == '\n' ? "" : "\n"; }

// The declarations of the two outputs and the call of the shader's own main.
std::string fragmentMain(const Flavour& f, const std::string& value, const std::string& info, const std::string& start) {
    std::string s;
    if (f.outs) {
        for (int k = 0; k < 2; ++k)
            s += (f.modern ? "layout(location = " + std::to_string(k) + ") " : std::string()) + "out " + f.hp +
                 "vec4 " + std::string(k ? kWatchInfoOut : kWatchValueOut) + ";\n";
        return s + "void main() { " + start + std::string(kWatchedMain) + "(); " + std::string(kWatchValueOut) + " = " +
               value + "; " + std::string(kWatchInfoOut) + " = " + info + "; }\n";
    }
    return "void main() { " + start + std::string(kWatchedMain) + "(); gl_FragData[0] = " + value +
           "; gl_FragData[1] = " + info + "; }\n";
}

// The shared part of the two stage rewrites that hold the capture.
WatchedStage capture(std::string_view source, int line, std::string_view expression, bool fragment) {
    WatchedStage out;
    if (std::string why = watchExpressionProblem(expression); !why.empty()) {
        out.error = why;
        return out;
    }
    const Code code(source);
    size_t start = lineStartOf(source, line);
    if (start == std::string_view::npos || start >= source.size()) {
        int lines = int(std::count(source.begin(), source.end(), '\n')) + (source.empty() || source.back() == '\n' ? 0 : 1);
        out.error = "the shader has " + std::to_string(lines) + " lines; there is no line " + std::to_string(line);
        return out;
    }
    // The line's last code token (code tokens never span lines).
    const auto after = std::upper_bound(code.tokens.begin(), code.tokens.end(), line,
                                        [](int l, const GlslToken& t) { return l < t.line; });
    if (after == code.tokens.begin() || (after - 1)->line != line) {
        out.column = 1;
        out.error = "line " + std::to_string(line) +
                    " holds no statement (it is blank, a comment or a directive): watch a line with one";
        return out;
    }
    const size_t last = size_t(after - code.tokens.begin()) - 1;
    out.column = int(code.tokens[last].end - start) + 1;
    const std::vector<Body> bodies = functionBodies(code);
    const Body* body = nullptr;
    for (const Body& b : bodies)
        if (last >= b.open && last <= b.close) body = &b;
    if (!body) {
        out.column = 1;
        out.error = "line " + std::to_string(line) +
                    " is outside any function: a watch goes on a line inside a function's body, such as main's";
        return out;
    }
    const std::string call = std::string(kWatchStore) + "(" + std::string(expression) + ");";
    // The line that opens the function: the value as the function starts;
    // the line that closes it: as it ends (unless it returned earlier).
    Placement p = last == body->open    ? Placement{true, "", {{code.tokens[last].end, 0, " " + call}}}
                  : last == body->close ? Placement{true, "", {{code.tokens[last].begin, 0, " " + call + " "}}}
                                        : placeCapture(code, *body, last, " " + call);
    if (!p.ok) {
        out.error = p.error;
        return out;
    }
    std::vector<GlslEdit> edits = p.edits;
    if (!renameMain(code, bodies, edits)) {
        out.error = "the shader has no main function to watch";
        return out;
    }
    const Flavour f = flavourOf(source);
    std::string globals = helpers(f);
    if (fragment) globals += outputsToGlobals(code, bodies, f, edits);
    edits.push_back({beforeFunctions(code, bodies), 0, globals});
    out.text = applyGlslEdits(source, edits) + lineEnding(source);
    out.ok = true;
    return out;
}

}  // namespace

WatchedStage watchFragment(std::string_view source, int line, std::string_view expression) {
    WatchedStage w = capture(source, line, expression, true);
    if (w.ok)
        w.text += fragmentMain(flavourOf(source), "glimmer_watch_v", "vec4(1., glimmer_watch_n * 0.25, glimmer_watch_k / 3., 1.)",
                               "glimmer_watch_n = 0.; ");
    return w;
}

WatchedStage watchVertex(std::string_view source, int line, std::string_view expression) {
    WatchedStage w = capture(source, line, expression, false);
    if (!w.ok) return w;
    const Flavour f = flavourOf(source);
    const std::string q = f.outs ? "out " + f.hp : "varying ";
    w.text += q + "vec4 glimmer_watch_vary;\n" + q + "vec2 glimmer_watch_vinfo;\n" + "void main() { glimmer_watch_n = 0.; " +
              std::string(kWatchedMain) + "(); glimmer_watch_vary = glimmer_watch_v; glimmer_watch_vinfo = "
                                          "vec2(glimmer_watch_n, glimmer_watch_k); }\n";
    return w;
}

WatchedStage watchFragmentOfVertex(std::string_view source) {
    WatchedStage out;
    const Code code(source);
    const std::vector<Body> bodies = functionBodies(code);
    std::vector<GlslEdit> edits;
    if (bodies.empty() || !renameMain(code, bodies, edits)) {
        out.error = "the program's fragment shader has no main function";
        return out;
    }
    const Flavour f = flavourOf(source);
    std::string globals = outputsToGlobals(code, bodies, f, edits);
    edits.push_back({beforeFunctions(code, bodies), 0, globals});
    const std::string q = f.outs ? "in " + f.hp : "varying ";
    out.text = applyGlslEdits(source, edits) + lineEnding(source) + q + "vec4 glimmer_watch_vary;\n" + q +
               "vec2 glimmer_watch_vinfo;\n" +
               fragmentMain(f, "glimmer_watch_vary", "vec4(1., glimmer_watch_vinfo * vec2(0.25, 1. / 3.), 1.)", "");
    out.ok = true;
    return out;
}

}  // namespace glimmer
