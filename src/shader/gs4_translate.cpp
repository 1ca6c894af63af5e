#include "shader/gs4_translate.h"
#include "shader/glsl_lexer.h"
#include "shader/glsl_scan.h"

#include <algorithm>
#include <charconv>
#include <map>

namespace glimmer {
namespace {

using Kind = GlslTokenKind;

// The tokens the translation reads: code and whole directives (it rewrites
// #version and drops #extension lines); blanks and comments left out.
std::vector<GlslToken> codeAndDirectives(std::string_view s) {
    std::vector<GlslToken> out = lexGlsl(s);
    out.erase(std::remove_if(out.begin(), out.end(),
                             [](const GlslToken& t) { return !isGlslCode(t.kind) && t.kind != Kind::Directive; }),
              out.end());
    return out;
}

// EXT per-vertex input arrays and the gl_in member each becomes.
const std::map<std::string_view, std::string_view>& inputArrays() {
    static const std::map<std::string_view, std::string_view> m = {
        {"gl_PositionIn", "gl_Position"},
        {"gl_PointSizeIn", "gl_PointSize"},
        {"gl_ClipVertexIn", "gl_ClipVertex"},
        {"gl_FrontColorIn", "gl_FrontColor"},
        {"gl_BackColorIn", "gl_BackColor"},
        {"gl_FrontSecondaryColorIn", "gl_FrontSecondaryColor"},
        {"gl_BackSecondaryColorIn", "gl_BackSecondaryColor"},
        {"gl_TexCoordIn", "gl_TexCoord"},
        {"gl_FogFragCoordIn", "gl_FogFragCoord"},
    };
    return m;
}

bool isPrimitiveWord(std::string_view w) {
    return w == "points" || w == "lines" || w == "lines_adjacency" || w == "triangles" ||
           w == "triangles_adjacency";
}

// "#  extension   GL_EXT_geometry_shader4 : enable" -> true
bool isGs4Extension(std::string_view d) {
    const std::vector<GlslToken> w = directiveTokens(d);
    return isWordToken(d, w, 0, "extension") && isWordToken(d, w, 1, "GL_EXT_geometry_shader4");
}

// "#version 120" -> 120; 0 when not a #version line.
int versionNumber(std::string_view d) {
    const std::vector<GlslToken> w = directiveTokens(d);
    if (!isWordToken(d, w, 0, "version") || w.size() < 2 || w[1].kind != Kind::Number) return 0;
    const std::string_view number = tokenText(d, w[1]);
    int v = 0;
    std::from_chars(number.data(), number.data() + number.size(), v);
    return v;
}

}  // namespace

Gs4Result translateGs4(std::string_view src, const Gs4Options& options) {
    Gs4Result r;
    const std::vector<GlslToken> toks = codeAndDirectives(src);
    std::vector<GlslEdit> edits;
    auto text = [&](size_t k) { return tokenText(src, toks[k]); };
    auto note = [&](std::string what, const GlslToken& at) {
        r.usesExt = true;
        if (!r.firstExtLine) r.firstExtLine = at.line;
        if (std::find(r.rewrites.begin(), r.rewrites.end(), what) == r.rewrites.end()) r.rewrites.push_back(std::move(what));
    };
    auto ident = [&](size_t k, std::string_view w) { return isWordToken(src, toks, k, w); };
    auto punct = [&](size_t k, char c) { return isPunctToken(src, toks, k, std::string_view(&c, 1)); };

    const GlslToken* version = nullptr;
    size_t firstCode = toks.size();  // the first token that is not a directive
    int depth = 0;                   // braces
    for (size_t k = 0; k < toks.size(); ++k) {
        const GlslToken& t = toks[k];
        const std::string_view tt = text(k);
        if (t.kind == Kind::Directive) {
            if (!version && versionNumber(tt)) version = &t;
            if (isGs4Extension(tt)) {
                // Keep the line (and any continued lines) so line numbers stay.
                edits.push_back({t.begin, t.end - t.begin,
                                 std::string(size_t(std::count(tt.begin(), tt.end(), '\n')), '\n')});
                note("#extension GL_EXT_geometry_shader4 dropped", t);
            }
            continue;
        }
        if (firstCode == toks.size()) firstCode = k;
        if (punct(k, '{')) ++depth;
        if (punct(k, '}')) depth = std::max(0, depth - 1);
        if (t.kind != Kind::Word) continue;

        if (auto it = inputArrays().find(tt); it != inputArrays().end() && punct(k + 1, '[')) {
            size_t close = k + 1;
            for (int nest = 0; close < toks.size(); ++close) {
                if (punct(close, '[')) ++nest;
                if (punct(close, ']') && --nest == 0) break;
            }
            if (close == toks.size()) continue;  // unbalanced: the compiler will say so
            edits.push_back({t.begin, tt.size(), "gl_in"});
            edits.push_back({toks[close].end, 0, "." + std::string(it->second)});
            std::string member(it->second);
            note(std::string(tt) + (tt == "gl_TexCoordIn" ? "[i][j] -> gl_in[i]." + member + "[j]"
                                                                    : "[i] -> gl_in[i]." + member),
                 t);
        } else if (tt == "gl_VerticesIn") {
            if (depth == 0 && k > 0 && punct(k - 1, '[') && punct(k + 1, ']')) {
                edits.push_back({t.begin, tt.size(), ""});  // an input array's size: unsized
                note("[gl_VerticesIn] -> []", t);
            } else {
                edits.push_back({t.begin, tt.size(), "gl_in.length()"});
                note("gl_VerticesIn -> gl_in.length()", t);
            }
        } else if (tt == "varying") {
            if (ident(k + 1, "in") || ident(k + 1, "out")) {
                bool blank = t.end < src.size() && (src[t.end] == ' ' || src[t.end] == '\t');
                edits.push_back({t.begin, tt.size() + (blank ? 1 : 0), ""});
                note(std::string("varying ") + std::string(text(k + 1)) + " -> " + std::string(text(k + 1)),
                     t);
            } else if (depth == 0) {
                edits.push_back({t.begin, tt.size(), "out"});
                note("varying -> out", t);
            }
        } else if (tt == "layout" && punct(k + 1, '(')) {
            size_t j = k + 2;
            bool primitive = false;
            for (; j < toks.size() && !punct(j, ')'); ++j) primitive |= toks[j].kind == Kind::Word && isPrimitiveWord(text(j));
            if (primitive && ident(j + 1, "in")) r.hasInputLayout = true;
        }
    }

    if (!r.hasInputLayout && !options.inputPrimitive.empty() && firstCode < toks.size()) {
        edits.push_back({toks[firstCode].begin, 0, "layout(" + options.inputPrimitive + ") in; "});
        r.addedInputLayout = true;
    }
    if (r.usesExt && version && versionNumber(tokenText(src, *version)) < 150) {
        edits.push_back({version->begin, version->end - version->begin, "#version 150 compatibility"});
        r.rewrites.push_back("#version " + std::to_string(versionNumber(tokenText(src, *version))) + " -> #version 150 compatibility");
    }

    r.text = applyGlslEdits(src, std::move(edits));
    return r;
}

}  // namespace glimmer
