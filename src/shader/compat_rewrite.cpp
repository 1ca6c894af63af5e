#include "shader/compat_rewrite.h"
#include "shader/glsl_lexer.h"
#include "shader/glsl_scan.h"

#include <algorithm>
#include <cstdlib>
#include <set>

#include "shader/compat_builtins.h"

namespace glimmer {
namespace {

// The old texture lookups and the GLSL 1.30 functions that replaced them.
struct TextureRename {
    std::string_view from, to;
};
constexpr TextureRename kTextureRenames[] = {
    {"texture1D", "texture"},         {"texture2D", "texture"},           {"texture3D", "texture"},
    {"textureCube", "texture"},       {"shadow2D", "texture"},            {"texture2DLod", "textureLod"},
    {"texture3DLod", "textureLod"},   {"textureCubeLod", "textureLod"},   {"texture2DProj", "textureProj"},
    {"texture3DProj", "textureProj"}, {"texture2DProjLod", "textureProjLod"},
    {"texture2DGrad", "textureGrad"}, {"textureCubeGrad", "textureGrad"},
};

// Fragment outputs: ES 3.00 has no gl_FragColor; location 0 is the target.
constexpr std::string_view kFragColor = "glimmer_FragColor";
constexpr std::string_view kFragData = "glimmer_FragData";
// ES 3.0 guarantees 4 draw buffers (GL_MAX_DRAW_BUFFERS), as many as
// gl_FragData may be indexed with there.
constexpr int kFragDataCount = 4;
constexpr std::string_view kFtransform = "glimmer_ftransform";
// The fixed-function varyings: gl_FrontColor written by the vertex stage is
// gl_Color read by the fragment stage; gl_TexCoord[k] is one varying per
// constant index (glimmer_TexCoord0, ...), so each stage declares only the
// ones it uses and the two still match by name.
constexpr std::string_view kFrontColor = "glimmer_FrontColor";
constexpr std::string_view kTexCoord = "glimmer_TexCoord";
// gl_MaxTextureCoords on Mesa and NVIDIA.
constexpr int kTexCoordCount = 8;

const CompatBuiltin* builtinNamed(std::string_view word) {
    for (const CompatBuiltin& b : kCompatBuiltins)
        if (b.builtin == word) return &b;
    return nullptr;
}

}  // namespace

std::map<std::string, std::string> definesOf(std::string_view prelude) {
    std::map<std::string, std::string> out;
    for (const GlslToken& t : lexGlsl(prelude)) {
        if (t.kind != GlslTokenKind::Directive) continue;
        const std::string_view d = tokenText(prelude, t);
        const std::vector<GlslToken> w = directiveTokens(d);  // define NAME VALUE
        if (w.size() < 3 || !isWordToken(d, w, 0, "define") || w[1].kind != GlslTokenKind::Word) continue;
        // "#define F(x) ..." is a macro with arguments, no alias: its third token is '('.
        if (w[2].kind != GlslTokenKind::Word && w[2].kind != GlslTokenKind::Number) continue;
        out[std::string(tokenText(d, w[1]))] = std::string(tokenText(d, w[2]));
    }
    return out;
}

CompatRewrite rewriteCompatBuiltins(std::string_view s, CompatStage stage,
                                    const std::map<std::string, std::string>& aliases) {
    CompatRewrite r;
    GlslVersion version = glslVersionOf(s);
    r.version = version.number;
    r.profile = version.profile;
    r.versionLine = version.line;
    const bool vertex = stage == CompatStage::Vertex;

    std::set<CompatFeed> used;
    std::set<int> texCoords;
    bool fragColor = false, fragData = false, ftransform = false, frontColor = false;
    std::string body;
    body.reserve(s.size() + 64);
    auto rename = [&](std::string_view to, std::string_view userSpelling) {
        body.append(to);
        r.renames.emplace(std::string(to), std::string(userSpelling));
    };

    // One token at a time: words are renamed, everything else is kept as
    // written. A directive's own words are renamed too (`#define COLOR
    // gl_FragColor`), so its text is lexed again, without the '#'.
    // `k` is advanced past what a rename consumed.
    // Every other word: its stand-in, its new spelling, or itself.
    auto renameWord = [&](std::string_view spelled, std::string_view word) {
        if ((vertex && word == "gl_FrontColor") || (!vertex && word == "gl_Color")) {
            rename(kFrontColor, spelled);
            frontColor = true;
        } else if (const CompatBuiltin* b = builtinNamed(word); b && (vertex || !b->attribute)) {
            rename(b->name, spelled);
            used.insert(b->feed);
        } else if (!vertex && word == "gl_FragColor") {
            rename(kFragColor, spelled);
            fragColor = true;
        } else if (!vertex && word == "gl_FragData") {
            rename(kFragData, spelled);
            fragData = true;
        } else if (vertex && word == "ftransform") {
            rename(kFtransform, spelled);
            ftransform = true;
            used.insert(CompatFeed::ModelViewProjection);
            used.insert(CompatFeed::Vertex);
        } else if (auto tex = std::find_if(std::begin(kTextureRenames), std::end(kTextureRenames),
                                           [&](const TextureRename& t) { return t.from == word; });
                   tex != std::end(kTextureRenames)) {
            rename(tex->to, spelled);
        } else if (word == "attribute" && vertex) {
            body += "in";
        } else if (word == "varying") {
            body += vertex ? "out" : "in";
        } else {
            body.append(word);  // an alias to a name with no stand-in is spelled as what it stands for
        }
    };
    auto rewrite = [&](std::string_view text, const std::vector<GlslToken>& toks, size_t from, size_t to) {
        // The next token from `k` on, blanks on the line skipped; npos past the end.
        auto next = [&](size_t k) {
            while (k < to && toks[k].kind == GlslTokenKind::Space) ++k;
            return k < to ? k : std::string_view::npos;
        };
        auto isPunct = [&](size_t k, std::string_view p) { return k != std::string_view::npos && isPunctToken(text, toks, k, p); };
        for (size_t k = from; k < to; ++k) {
            const GlslToken& t = toks[k];
            if (t.kind != GlslTokenKind::Word) {
                body.append(tokenText(text, t));
                continue;
            }
            const std::string_view spelled = tokenText(text, t);
            std::string_view word = spelled;
            if (auto a = aliases.find(std::string(word)); a != aliases.end()) word = a->second;
            if (word == "gl_Point") {  // gl_Point.size: a member, renamed whole
                const size_t dot = next(k + 1), m = isPunct(dot, ".") ? next(dot + 1) : std::string_view::npos;
                if (m != std::string_view::npos && isWordToken(text, toks, m, "size")) {
                    const CompatBuiltin& b = compatBuiltin(CompatFeed::PointSize);
                    rename(b.name, "gl_Point");
                    used.insert(b.feed);
                    k = m;
                    continue;
                }
            }
            if (word == "gl_TexCoord") {  // gl_TexCoord[k], k a literal: one varying per index
                const size_t open = next(k + 1), d = isPunct(open, "[") ? next(open + 1) : std::string_view::npos;
                const size_t close = d == std::string_view::npos ? d : next(d + 1);
                const std::string_view digits = d != std::string_view::npos && toks[d].kind == GlslTokenKind::Number
                                                    ? tokenText(text, toks[d]) : "";
                const bool literal = !digits.empty() && digits.size() < 3 &&
                                     std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
                const int index = literal ? std::atoi(std::string(digits).c_str()) : -1;
                if (index >= 0 && index < kTexCoordCount && isPunct(close, "]")) {
                    rename(std::string(kTexCoord) + std::to_string(index), "gl_TexCoord");
                    texCoords.insert(index);
                    k = close;
                    continue;
                }
            }
            renameWord(spelled, word);
        }
    };
    const std::vector<GlslToken> tokens = lexGlsl(s);
    size_t run = 0;  // the first token not yet rewritten
    for (size_t k = 0; k <= tokens.size(); ++k) {
        if (k < tokens.size() && tokens[k].kind != GlslTokenKind::Directive) continue;
        rewrite(s, tokens, run, k);
        run = k + 1;
        if (k == tokens.size()) break;
        const std::string_view text = tokenText(s, tokens[k]);
        if (tokens[k].line == r.versionLine) {  // the header says the version now; its lines stay
            body.append(size_t(std::count(text.begin(), text.end(), '\n')), '\n');
            continue;
        }
        body += '#';
        const std::string_view rest = text.substr(1);
        const std::vector<GlslToken> inDirective = lexGlsl(rest);
        rewrite(rest, inDirective, 0, inDirective.size());
    }

    // The header: a version glslang compiles for OpenGL SPIR-V, then what
    // the renames introduced, then the user's lines numbered from 1.
    std::string head = "#version " + std::to_string(std::max(330, r.version)) + " core\n";
    for (const CompatBuiltin& b : kCompatBuiltins) {
        if (!used.count(b.feed)) continue;
        if (b.attribute)
            head += "layout(location = " + std::to_string(b.location) + ") in " + std::string(b.glslType) + " " +
                    std::string(b.name) + ";\n";
        else head += "uniform " + std::string(b.glslType) + " " + std::string(b.name) + ";\n";
        r.declared.emplace_back(b.name);
    }
    // The fixed-function varyings: out of the vertex stage, into the fragment stage.
    const std::string direction = vertex ? "out" : "in";
    if (frontColor) {
        head += direction + " vec4 " + std::string(kFrontColor) + ";\n";
        r.declared.emplace_back(kFrontColor);
    }
    for (int k : texCoords) {
        head += direction + " vec4 " + std::string(kTexCoord) + std::to_string(k) + ";\n";
        r.declared.push_back(std::string(kTexCoord) + std::to_string(k));
    }
    if (fragColor) {
        head += "layout(location = 0) out vec4 " + std::string(kFragColor) + ";\n";
        r.declared.emplace_back(kFragColor);
    }
    if (fragData && !fragColor) {  // both: the compiler says they clash, at the user's line
        head += "layout(location = 0) out vec4 " + std::string(kFragData) + "[" + std::to_string(kFragDataCount) + "];\n";
        r.declared.emplace_back(kFragData);
    }
    if (ftransform) {
        head += "vec4 " + std::string(kFtransform) + "() { return " +
                std::string(compatBuiltin(CompatFeed::ModelViewProjection).name) + " * " +
                std::string(compatBuiltin(CompatFeed::Vertex).name) + "; }\n";
        r.declared.emplace_back(kFtransform);
    }
    r.text = head + "#line 1\n" + body;
    return r;
}

}  // namespace glimmer
