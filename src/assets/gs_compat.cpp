#include "assets/gs_compat.h"

#include <filesystem>
#include <set>

#include <fmt/format.h>

#include "shader/gs4_translate.h"

namespace glimmer {
namespace {

const char* layoutWord(Mesh::Primitive p) {
    switch (p) {
    case Mesh::Primitive::Triangles: return "triangles";
    case Mesh::Primitive::Lines: return "lines";
    case Mesh::Primitive::Points: return "points";
    case Mesh::Primitive::LinesAdjacency: return "lines_adjacency";
    case Mesh::Primitive::TrianglesAdjacency: return "triangles_adjacency";
    case Mesh::Primitive::Patches: return "";
    }
    return "";
}

struct DrawPrimitive {
    std::string word;
    SourceLoc loc;
};

// The input primitives of the draws with `program`, in script order, one per kind.
std::vector<DrawPrimitive> drawPrimitives(const Plan& plan, const Assets& assets, int program) {
    std::vector<DrawPrimitive> out;
    for (const auto& pass : plan.passes)
        for (const auto& st : pass.steps) {
            if (st.kind != Step::Kind::Draw || st.draw.program != program) continue;
            int m = st.draw.mesh;
            if (m < 0 || size_t(m) >= assets.meshes.size() || !assets.meshes[size_t(m)]) continue;
            std::string word = layoutWord(assets.meshes[size_t(m)]->primitive);
            bool known = false;
            for (const auto& d : out) known |= d.word == word;
            if (!known && !word.empty()) out.push_back({word, st.draw.loc});
        }
    return out;
}

std::string joined(const std::vector<std::string>& items) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
    return s;
}

}  // namespace

void adaptGeometryShaders(const Plan& plan, Assets& assets, Diagnostics& diags) {
    const std::string scriptName = std::filesystem::path(plan.scriptFile).filename().string();
    std::set<std::string> announced;
    for (size_t i = 0; i < plan.programs.size() && i < assets.shaderTexts.size(); ++i) {
        const ProgramDecl& p = plan.programs[i];
        bool tessellated = false;
        for (const auto& st : p.stages) tessellated |= st.kind == ShaderStage::Kind::TessEvaluation;
        for (size_t k = 0; k < p.stages.size() && k < assets.shaderTexts[i].size(); ++k) {
            const ShaderStage& stage = p.stages[k];
            auto& text = assets.shaderTexts[i][k];
            if (stage.kind != ShaderStage::Kind::Geometry || !text) continue;
            // With tessellation the geometry shader's input is what the
            // evaluation shader makes, not the draw's primitive.
            std::vector<DrawPrimitive> draws;
            if (!tessellated) draws = drawPrimitives(plan, assets, int(i));
            Gs4Options options;
            if (!draws.empty()) options.inputPrimitive = draws.front().word;
            Gs4Result r = translateGs4(*text, options);
            if (!r.changed()) continue;
            *text = std::move(r.text);
            if (r.addedInputLayout && draws.size() > 1)
                diags.warning(plan.scriptFile, draws[1].loc,
                              fmt::format("Program {}'s geometry shader '{}' declares no input primitive and takes {} "
                                          "from its first draw (line {}); this shape gives {}",
                                          p.name, stage.shown, draws[0].word, draws[0].loc.line, draws[1].word));
            if (!announced.insert(stage.path).second) continue;
            std::string layout = r.addedInputLayout
                                     ? fmt::format("layout({}) in; added from the draw on line {} of {}",
                                                   draws.front().word, draws.front().loc.line, scriptName)
                                     : "";
            if (r.usesExt)
                diags.warning(stage.path, {r.firstExtLine, 1},
                              fmt::format("GL_EXT_geometry_shader4 shader (NVIDIA) translated to standard GLSL: {}{}",
                                          joined(r.rewrites), layout.empty() ? "" : "; " + layout));
            else
                diags.warning(plan.scriptFile, draws.front().loc,
                              fmt::format("geometry shader '{}' declares no input primitive; {}", stage.shown, layout));
        }
    }
}

}  // namespace glimmer
