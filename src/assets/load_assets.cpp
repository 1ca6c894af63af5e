#include "assets/assets.h"


#include <set>

#include <fmt/format.h>

#include "assets/gs_compat.h"
#include "assets/stand_ins.h"
#include "shader/precision_strip.h"
#include "image/cubemap.h"
#include "plan/limits.h"
#include "plan/memory_budget.h"
#include "util/read_file.h"

namespace glimmer {
namespace {

bool loadTexture(const TextureDecl& t, TextureFile& out, std::string& why) {
    if (t.source != TextureDecl::Source::File) return true;  // a target, or an empty 3-D texture
    if (needsStandIn(t)) return standInTexture(t, out, why);   // --stand-ins: the plan warned
    if (t.kind == TextureDecl::Kind::Cube) {
        std::array<std::string, 6> paths;
        for (size_t k = 0; k < 6; ++k) paths[k] = t.facePaths.at(k);
        out.loaded = loadCubeMap(paths, out.faces, why);
    } else if (t.kind == TextureDecl::Kind::Tex3D) {
        out.loaded = loadVolume(t.path, out.volume, why);
    } else {
        out.loaded = loadImage(t.path, out.image, why);
    }
    return out.loaded;
}

std::uint64_t decodedBytes(const TextureFile& f) {
    auto bytes = [](const Image& i) { return std::uint64_t(i.u8.size()) + std::uint64_t(i.f32.size()) * 4; };
    std::uint64_t total = bytes(f.image) + std::uint64_t(f.volume.u8.size()) + std::uint64_t(f.volume.f32.size()) * 4;
    for (const auto& face : f.faces) total += bytes(face);
    return total;
}

// Only a regular file, and never more than kMaxShaderBytes (util/read_file.h).
std::optional<std::string> readShader(const ShaderStage& stage, std::string& why) {
    std::string text;
    if (!readRegularFile(stage.path, kMaxShaderBytes, text, why)) return std::nullopt;
    return text;
}

}  // namespace

bool loadAssets(const Plan& plan, bool everything, Diagnostics& diags, SourceTexts& sources, Assets& out) {
    const std::string& file = plan.scriptFile;
    int errorsBefore = diags.errorCount();
    out.used = resourcesUsed(plan, everything);
    out.textures.assign(plan.textures.size(), {});
    out.meshes.assign(plan.meshes.size(), std::nullopt);
    out.shaderTexts.assign(plan.programs.size(), {});

    // Image files count against --max-memory with what the plan declares;
    // each was already bounded by the image limits before it was decoded.
    std::uint64_t total = plannedBytes(plan);
    bool overBudget = false;
    for (size_t i = 0; i < plan.textures.size(); ++i) {
        if (!out.used.textures[i]) continue;
        const TextureDecl& t = plan.textures[i];
        std::string why;
        if (!loadTexture(t, out.textures[i], why)) {
            diags.error(file, t.loc, fmt::format("cannot load '{}': {}", t.shown, why));
            continue;
        }
        total += decodedBytes(out.textures[i]);
        if (plan.maxMemoryBytes > 0 && total > plan.maxMemoryBytes) {
            if (!overBudget) reportOverBudget(plan, t.loc, total, diags);  // the first line past it
            overBudget = true;
            out.textures[i] = {};
        }
    }
    for (size_t i = 0; i < plan.meshes.size() && !overBudget; ++i) {
        if (!out.used.meshes[i]) continue;
        Mesh mesh;
        std::string why;
        if (needsStandIn(plan.meshes[i])) out.meshes[i] = standInMesh(plan.meshes[i]);  // --stand-ins
        else if (buildMesh(plan.meshes[i], mesh, why, total, plan.maxMemoryBytes)) out.meshes[i] = std::move(mesh);
        else diags.error(file, plan.meshes[i].loc, why);
        // A shape counts once built: the counts bound each (geometry/shape_registry.h),
        // so the budget is passed by at most one shape, and never kept past.
        if (!out.meshes[i]) continue;
        total += meshBytes(*out.meshes[i]);
        if (plan.maxMemoryBytes > 0 && total > plan.maxMemoryBytes) {
            reportOverBudget(plan, plan.meshes[i].loc, total, diags);
            out.meshes[i].reset();
            overBudget = true;
        }
    }
    for (size_t i = 0; i < plan.programs.size(); ++i) {
        if (!out.used.programs[i]) continue;
        for (const auto& stage : plan.programs[i].stages) {
            std::string why;
            auto text = readShader(stage, why);
            // A UTF-8 byte-order mark (Notepad writes one) before #version:
            // every GLSL compiler refuses it ("unexpected HASH_TOKEN"), the
            // student sees nothing wrong. Three blanks keep the columns.
            if (text && text->compare(0, 3, "\xEF\xBB\xBF") == 0) {
                text->replace(0, 3, "   ");
                diags.note(stage.path, {1, 1}, "a UTF-8 byte-order mark starts this file (an editor put it there); "
                                               "read as blanks, since GLSL compilers refuse it");
            }
            if (text) sources.add(stage.path, *text);
            else diags.error(file, stage.loc, fmt::format("cannot read shader '{}': it {}", stage.shown, why));
            out.shaderTexts[i].push_back(std::move(text));
        }
    }
    adaptGeometryShaders(plan, out, diags);  // NVIDIA-era geometry shaders -> standard GLSL
    // ES precision qualifiers before GLSL 1.30, which NVIDIA accepts and Mesa
    // refuses; they mean nothing on desktop GL. One warning per file.
    std::set<std::string> stripped;
    for (size_t i = 0; i < plan.programs.size(); ++i)
        for (size_t k = 0; k < plan.programs[i].stages.size() && k < out.shaderTexts[i].size(); ++k) {
            auto& text = out.shaderTexts[i][k];
            if (!text) continue;
            PrecisionStripResult r = stripPrecisionQualifiers(*text);
            if (!r.changed()) continue;
            *text = std::move(r.text);
            const ShaderStage& stage = plan.programs[i].stages[k];
            if (stripped.insert(stage.path).second)
                diags.warning(stage.path, {r.firstLine, 1},
                              "precision qualifiers (OpenGL ES; NVIDIA accepts them) removed: GLSL before 1.30 "
                              "has none, and on desktop OpenGL they change nothing");
        }
    return diags.errorCount() == errorsBefore;
}

}  // namespace glimmer
