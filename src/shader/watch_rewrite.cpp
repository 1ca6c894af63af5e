#include "shader/watch_rewrite.h"

#include <algorithm>
#include <vector>

#include "shader/glsl_scan.h"

namespace glimmer {
namespace {

constexpr std::string_view kWatchedMain = "glimmer_watched_main";
constexpr int kMaxWatchLine = 1000000;

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// `text` with comments and preprocessor lines blanked (newlines kept), so
// the scan below sees only code, at the offsets of the original.
std::string codeOnly(std::string_view text) {
    std::string s = blankComments(text);
    bool continued = false;
    for (size_t i = 0; i < s.size();) {
        size_t end = s.find('\n', i);
        if (end == std::string::npos) end = s.size();
        size_t p = i;
        while (p < end && (s[p] == ' ' || s[p] == '\t')) ++p;
        if (continued || (p < end && s[p] == '#')) {
            continued = end > i && s[end - 1] == '\\';  // a directive continued on the next line
            std::fill(s.begin() + std::ptrdiff_t(i), s.begin() + std::ptrdiff_t(end), ' ');
        }
        i = end + 1;
    }
    return s;
}

struct Edit {
    size_t at = 0;
    size_t erase = 0;
    std::string insert;
};

// Applies edits that do not overlap; two at one offset keep their order.
std::string applyEdits(std::string_view text, std::vector<Edit> edits) {
    std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.at < b.at; });
    std::string out;
    size_t pos = 0;
    for (const Edit& e : edits) {
        if (e.at < pos) continue;  // overlapping: cannot happen for the edits made here
        out.append(text.substr(pos, e.at - pos));
        out += e.insert;
        pos = e.at + e.erase;
    }
    if (pos < text.size()) out.append(text.substr(pos));
    return out;
}

struct Body {
    size_t declStart, open, close;  // where its declaration starts, its '{' and matching '}' (npos: never closed)
};

// The bodies of the functions defined at file scope: a top-level '{' right
// after a ')'. A struct's or block's braces are not bodies.
std::vector<Body> functionBodies(std::string_view code) {
    std::vector<Body> bodies;
    size_t declStart = 0;
    int depth = 0;
    for (size_t i = 0; i < code.size(); ++i) {
        char c = code[i];
        if (c == '{') {
            size_t j = i;
            while (j > 0 && isBlank(code[j - 1])) --j;
            if (depth == 0 && j > 0 && code[j - 1] == ')') {
                int d = 1;
                size_t k = i + 1;
                for (; k < code.size() && d > 0; ++k) d += code[k] == '{' ? 1 : code[k] == '}' ? -1 : 0;
                size_t close = d == 0 ? k - 1 : std::string_view::npos;
                bodies.push_back({declStart, i, close});
                if (close == std::string_view::npos) break;
                i = close;
                declStart = close + 1;
                continue;
            }
            ++depth;
        } else if (c == '}') {
            depth = std::max(0, depth - 1);
            if (depth == 0) declStart = i + 1;
        } else if (c == ';' && depth == 0) {
            declStart = i + 1;
        }
    }
    return bodies;
}

// `bodies` are in the order of the text and never overlap: the one that
// could hold `at` is the last that opens before it (a binary search; issue
// 38: a scan of every body for every character watched a shader of 80,000
// small functions in 209 s).
bool inBody(const std::vector<Body>& bodies, size_t at) {
    auto after = std::upper_bound(bodies.begin(), bodies.end(), at, [](size_t a, const Body& b) { return a <= b.open; });
    if (after == bodies.begin()) return false;
    const Body& b = *(after - 1);
    return at > b.open && at < b.close;
}

std::string wordAt(std::string_view code, size_t i) {
    size_t e = i;
    while (e < code.size() && isGlslWordChar(code[e])) ++e;
    return std::string(code.substr(i, e - i));
}

// Where on the watched line the capture goes. The statement that holds the
// line's last character is found by a scan of its function's body from the
// top: statements end at a ';' outside brackets, blocks open and close at
// braces, and the body of an if / for / while / else / do without braces
// starts after its header.
struct Placement {
    bool ok = false;
    std::string error;
    std::vector<Edit> edits;
};
Placement placeCapture(std::string_view code, const Body& body, size_t lastChar, const std::string& capture) {
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
    const size_t end = std::min(body.close, code.size());
    for (size_t i = body.open + 1; i < end; ++i) {
        char c = code[i];
        if (isGlslWordStart(c) && (i == 0 || !isGlslWordChar(code[i - 1]))) {
            std::string w = wordAt(code, i);
            if (paren == 0) {
                const bool doTail = afterDoBody && w == "while";
                afterDoBody = false;
                if (doTail) doDepths.pop_back();
                else if (w == "if" || w == "for" || w == "while" || w == "switch") pendingControl = true;
                if (w == "else" || w == "do") stmtStart = i + w.size(), controlBody = true;
                if (w == "do") doDepths.push_back(depth);
            }
            i += w.size() - 1;
            continue;
        }
        if (c == '(' || c == '[') {
            if (paren == 0 && pendingControl && c == '(') inHeader = true, pendingControl = false;
            ++paren;
        } else if (c == ')' || c == ']') {
            paren = std::max(0, paren - 1);
            if (paren == 0 && inHeader) inHeader = false, stmtStart = i + 1, controlBody = true;
        } else if (paren == 0 && (c == '{' || c == '}')) {
            if (i >= lastChar) {
                // A block opens on the line: the value at its start; a block
                // closes: the value at its end (each pass of a loop).
                return {true, "", {{c == '{' ? i + 1 : i, 0, capture}}};
            }
            depth = c == '{' ? depth + 1 : std::max(0, depth - 1);
            afterDoBody = c == '}' && !doDepths.empty() && depth == doDepths.back();
            stmtStart = i + 1, controlBody = false, pendingControl = false;
        } else if (paren == 0 && c == ';') {
            if (i >= lastChar) {
                size_t first = stmtStart;
                while (first < i && isBlank(code[first])) ++first;
                std::string w = wordAt(code, first);
                bool jump = w == "return" || w == "discard" || w == "break" || w == "continue";
                // A jump is watched just before it leaves; the lone body of an
                // if or a loop gets braces, so the capture stays inside it.
                std::vector<Edit> edits;
                if (controlBody) edits.push_back({first, 0, "{ "});
                if (jump) edits.push_back({first, 0, capture + " "});
                else edits.push_back({i + 1, 0, capture});
                if (controlBody) edits.push_back({i + 1, 0, " }"});
                return {true, "", edits};
            }
            afterDoBody = !doDepths.empty() && depth == doDepths.back() && controlBody;
            stmtStart = i + 1, controlBody = false, pendingControl = false;
        }
    }
    return {false, "the statement on this line never ends (no ';' or brace before the function's end)", {}};
}

// `old` as a whole word outside comments, directives and strings-of-nothing:
// every place, for a rename.
void renameWord(std::string_view code, std::string_view old, std::string_view now, std::vector<Edit>& edits,
                bool& found) {
    for (size_t at = code.find(old); at != std::string_view::npos; at = code.find(old, at + old.size())) {
        if (!isWholeWordAt(code, at, old.size())) continue;
        edits.push_back({at, old.size(), std::string(now)});
        found = true;
    }
}

// The fragment stage's own outputs become plain globals: `out` (and the
// `layout(...)` before it) at file scope is blanked, so the declarations
// stay where they are and keep their columns.
void demoteOutputs(std::string_view code, const std::vector<Body>& bodies, std::vector<Edit>& edits) {
    int paren = 0, depth = 0;
    size_t layoutAt = std::string_view::npos, layoutEnd = 0;
    for (size_t i = 0; i < code.size(); ++i) {
        char c = code[i];
        if (inBody(bodies, i)) continue;
        if (c == '(') ++paren;
        else if (c == ')') paren = std::max(0, paren - 1), layoutEnd = i + 1;
        else if (c == '{') ++depth;
        else if (c == '}') depth = std::max(0, depth - 1);
        else if (c == ';') layoutAt = std::string_view::npos;
        if (!isGlslWordStart(c) || (i > 0 && isGlslWordChar(code[i - 1])) || paren || depth) continue;
        std::string w = wordAt(code, i);
        if (w == "layout") layoutAt = i;
        if (w == "out") {
            edits.push_back({i, 3, "   "});
            if (layoutAt != std::string_view::npos && layoutEnd > layoutAt)
                edits.push_back({layoutAt, layoutEnd - layoutAt, std::string(layoutEnd - layoutAt, ' ')});
            layoutAt = std::string_view::npos;
        }
        i += w.size() - 1;
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
bool renameMain(std::string_view code, const std::vector<Body>& bodies, std::vector<Edit>& edits) {
    bool found = false;
    for (size_t at = code.find("main"); at != std::string_view::npos; at = code.find("main", at + 4)) {
        if (!isWholeWordAt(code, at, 4) || inBody(bodies, at)) continue;
        size_t q = at + 4;
        while (q < code.size() && isBlank(code[q])) ++q;
        if (q < code.size() && code[q] == '(') edits.push_back({at, 4, std::string(kWatchedMain)}), found = true;
    }
    return found;
}

// What the fragment stage wrote becomes globals of the same names (renamed
// built-ins, demoted `out`s): the added main writes the watch's two outputs
// instead. Returns the declarations the renamed built-ins need.
std::string outputsToGlobals(std::string_view code, const std::vector<Body>& bodies, const Flavour& f,
                             std::vector<Edit>& edits) {
    bool color = false, data = false;
    renameWord(code, "gl_FragColor", "glimmer_watch_FragColor", edits, color);
    renameWord(code, "gl_FragData", "glimmer_watch_FragData", edits, data);
    if (f.outs) demoteOutputs(code, bodies, edits);
    return std::string(color ? "vec4 glimmer_watch_FragColor; " : "") + (data ? "vec4 glimmer_watch_FragData[8]; " : "");
}

// Where declarations may go ahead of every function: the start of the first
// function's declaration, on its own line (so no line moves).
size_t beforeFunctions(std::string_view code, const std::vector<Body>& bodies) {
    size_t first = bodies.front().declStart;
    while (first < code.size() && isBlank(code[first])) ++first;
    return first;
}

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
    const std::string code = codeOnly(source);
    size_t start = lineStartOf(source, line);
    if (start == std::string_view::npos || start >= source.size()) {
        int lines = int(std::count(source.begin(), source.end(), '\n')) + (source.empty() || source.back() == '\n' ? 0 : 1);
        out.error = "the shader has " + std::to_string(lines) + " lines; there is no line " + std::to_string(line);
        return out;
    }
    size_t end = source.find('\n', start);
    if (end == std::string_view::npos) end = source.size();
    size_t last = end;
    for (size_t i = start; i < end; ++i)
        if (!isBlank(code[i])) last = i;
    if (last == end) {
        out.column = 1;
        out.error = "line " + std::to_string(line) +
                    " holds no statement (it is blank, a comment or a directive): watch a line with one";
        return out;
    }
    out.column = int(last - start) + 2;
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
    Placement p = last == body->open    ? Placement{true, "", {{last + 1, 0, " " + call}}}
                  : last == body->close ? Placement{true, "", {{last, 0, " " + call + " "}}}
                                        : placeCapture(code, *body, last, " " + call);
    if (!p.ok) {
        out.error = p.error;
        return out;
    }
    std::vector<Edit> edits = p.edits;
    if (!renameMain(code, bodies, edits)) {
        out.error = "the shader has no main function to watch";
        return out;
    }
    const Flavour f = flavourOf(source);
    std::string globals = helpers(f);
    if (fragment) globals += outputsToGlobals(code, bodies, f, edits);
    edits.push_back({beforeFunctions(code, bodies), 0, globals});
    out.text = applyEdits(source, edits) + lineEnding(source);
    out.ok = true;
    return out;
}

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
    const std::string code = codeOnly(source);
    const std::vector<Body> bodies = functionBodies(code);
    std::vector<Edit> edits;
    if (bodies.empty() || !renameMain(code, bodies, edits)) {
        out.error = "the program's fragment shader has no main function";
        return out;
    }
    const Flavour f = flavourOf(source);
    std::string globals = outputsToGlobals(code, bodies, f, edits);
    edits.push_back({beforeFunctions(code, bodies), 0, globals});
    const std::string q = f.outs ? "in " + f.hp : "varying ";
    out.text = applyEdits(source, edits) + lineEnding(source) + q + "vec4 glimmer_watch_vary;\n" + q +
               "vec2 glimmer_watch_vinfo;\n" +
               fragmentMain(f, "glimmer_watch_vary", "vec4(1., glimmer_watch_vinfo * vec2(0.25, 1. / 3.), 1.)", "");
    out.ok = true;
    return out;
}

}  // namespace glimmer
