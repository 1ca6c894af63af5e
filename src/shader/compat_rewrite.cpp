#include "shader/compat_rewrite.h"
#include "shader/glsl_scan.h"

#include <algorithm>
#include <cctype>
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

// Skips blanks from `i`; the index of the next other character.
size_t skipBlanks(std::string_view s, size_t i) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    return i;
}

}  // namespace

std::map<std::string, std::string> definesOf(std::string_view prelude) {
    std::map<std::string, std::string> out;
    size_t at = 0;
    while (at < prelude.size()) {
        size_t end = prelude.find('\n', at);
        if (end == std::string_view::npos) end = prelude.size();
        std::string_view l = prelude.substr(at, end - at);
        at = end + 1;
        size_t p = skipBlanks(l, 0);
        if (l.compare(p, 7, "#define") != 0) continue;
        p = skipBlanks(l, p + 7);
        size_t q = p;
        while (q < l.size() && isGlslWordChar(l[q])) ++q;
        size_t r = skipBlanks(l, q), e = r;
        while (e < l.size() && isGlslWordChar(l[e])) ++e;
        if (q > p && e > r) out[std::string(l.substr(p, q - p))] = std::string(l.substr(r, e - r));
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

    int line = 1;
    bool lineStart = true;
    for (size_t i = 0; i < s.size();) {
        char c = s[i];
        if (c == '\n') {
            body += c;
            ++line;
            lineStart = true;
            ++i;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r') {
            body += c;
            ++i;
            continue;
        }
        if (lineStart && c == '#' && line == r.versionLine) {  // the header says the version now
            while (i < s.size() && s[i] != '\n') ++i;
            continue;
        }
        lineStart = false;
        if (size_t end = commentEnd(s, i); end != i) {  // kept as written
            for (size_t k = i; k < end; ++k) line += s[k] == '\n';
            body.append(s.substr(i, end - i));
            i = end;
            continue;
        }
        if (!isGlslWordStart(c)) {  // numbers (1e5, 0x1Fu) whole, so no suffix is read as a word
            size_t j = i + 1;
            if (std::isdigit(static_cast<unsigned char>(c)))
                while (j < s.size() && (isGlslWordChar(s[j]) || s[j] == '.')) ++j;
            body.append(s.substr(i, j - i));
            i = j;
            continue;
        }
        size_t j = i;
        while (j < s.size() && isGlslWordChar(s[j])) ++j;
        std::string_view spelled = s.substr(i, j - i);
        std::string_view word = spelled;
        if (auto a = aliases.find(std::string(word)); a != aliases.end()) word = a->second;
        i = j;

        if (word == "gl_Point") {  // gl_Point.size: a member, renamed whole
            size_t dot = skipBlanks(s, j);
            size_t m = dot < s.size() && s[dot] == '.' ? skipBlanks(s, dot + 1) : std::string_view::npos;
            if (m != std::string_view::npos && s.compare(m, 4, "size") == 0 && (m + 4 == s.size() || !isGlslWordChar(s[m + 4]))) {
                const CompatBuiltin& b = compatBuiltin(CompatFeed::PointSize);
                rename(b.name, "gl_Point");
                used.insert(b.feed);
                i = m + 4;
                continue;
            }
        }
        if (word == "gl_TexCoord") {  // gl_TexCoord[k], k a literal: one varying per index
            size_t open = skipBlanks(s, j), d = open + 1;
            if (open < s.size() && s[open] == '[') {
                d = skipBlanks(s, open + 1);
                size_t e = d;
                while (e < s.size() && std::isdigit(static_cast<unsigned char>(s[e]))) ++e;
                size_t close = skipBlanks(s, e);
                int k = e > d && e - d < 3 ? std::atoi(std::string(s.substr(d, e - d)).c_str()) : -1;
                if (k >= 0 && k < kTexCoordCount && close < s.size() && s[close] == ']') {
                    std::string name = std::string(kTexCoord) + std::to_string(k);
                    rename(name, "gl_TexCoord");
                    texCoords.insert(k);
                    i = close + 1;
                    continue;
                }
            }
        }
        if ((vertex && word == "gl_FrontColor") || (!vertex && word == "gl_Color")) {
            rename(kFrontColor, spelled);
            frontColor = true;
            continue;
        }
        if (const CompatBuiltin* b = builtinNamed(word); b && (vertex || !b->attribute)) {
            rename(b->name, spelled);
            used.insert(b->feed);
            continue;
        }
        if (!vertex && word == "gl_FragColor") {
            rename(kFragColor, spelled);
            fragColor = true;
            continue;
        }
        if (!vertex && word == "gl_FragData") {
            rename(kFragData, spelled);
            fragData = true;
            continue;
        }
        if (vertex && word == "ftransform") {
            rename(kFtransform, spelled);
            ftransform = true;
            used.insert(CompatFeed::ModelViewProjection);
            used.insert(CompatFeed::Vertex);
            continue;
        }
        auto tex = std::find_if(std::begin(kTextureRenames), std::end(kTextureRenames),
                                [&](const TextureRename& t) { return t.from == word; });
        if (tex != std::end(kTextureRenames)) {
            rename(tex->to, spelled);
            continue;
        }
        if (word == "attribute" && vertex) {
            body += "in";
            continue;
        }
        if (word == "varying") {
            body += vertex ? "out" : "in";
            continue;
        }
        body.append(word);  // an alias to a name with no stand-in is spelled as what it stands for
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
