#include "plan/memory_budget.h"

#include <fmt/format.h>

namespace glimmer {

std::uint64_t textureBytes(const TextureDecl& t) {
    if (t.source != TextureDecl::Source::Empty) return 0;
    const std::uint64_t w = std::uint64_t(t.width), h = std::uint64_t(t.height);
    if (t.kind == TextureDecl::Kind::Tex3D) return w * h * std::uint64_t(t.depth) * 4;
    std::uint64_t texel = 4;
    if (t.format == TextureDecl::Format::RGBA16F) texel = 8;
    if (t.format == TextureDecl::Format::RGBA32F) texel = 16;
    std::uint64_t bytes = w * h * texel;
    if (t.mips) bytes += bytes / 3;
    if (t.needsDepth) bytes += w * h * 4;
    return bytes;
}

namespace {
std::uint64_t screenBytes(const Plan& plan) {
    return std::uint64_t(plan.width) * std::uint64_t(plan.height) * 8;  // colour and depth
}
}  // namespace

std::uint64_t plannedBytes(const Plan& plan) {
    std::uint64_t total = screenBytes(plan) + plan.scriptBytes;
    if (plan.noise2DLoc.line > 0) total += noiseBytes(2, plan.noise2DRes);
    if (plan.noise3DLoc.line > 0) total += noiseBytes(3, plan.noise3DRes);
    for (const auto& t : plan.textures) total += textureBytes(t);
    return total;
}

void reportOverBudget(const Plan& plan, SourceLoc loc, std::uint64_t total, Diagnostics& diags) {
    diags.error(plan.scriptFile, loc, overMemoryBudget(total, plan.maxMemoryBytes));
}

std::uint64_t noiseBytes(int dims, int res) {
    // The four float channels made on the CPU, the 8-bit texel they become
    // and its copy on the GPU (image/noise.h): 24 bytes a texel.
    std::uint64_t texels = std::uint64_t(res) * std::uint64_t(res) * (dims == 3 ? std::uint64_t(res) : 1);
    return texels * 24;
}

void checkMemoryBudget(const Plan& plan, std::uint64_t budget, Diagnostics& diags) {
    std::uint64_t total = screenBytes(plan) + plan.scriptBytes;
    // A noise resolution the script sets is charged at its line: made only
    // for programs that read Noise2/Noise3, but a script cannot ask for
    // more than it may have.
    for (int dims : {2, 3}) {
        const SourceLoc loc = dims == 2 ? plan.noise2DLoc : plan.noise3DLoc;
        if (loc.line <= 0) continue;
        total += noiseBytes(dims, dims == 2 ? plan.noise2DRes : plan.noise3DRes);
        if (total > budget) {
            reportOverBudget(plan, loc, total, diags);
            return;
        }
    }
    for (const auto& t : plan.textures) {
        total += textureBytes(t);
        if (total > budget) {
            reportOverBudget(plan, t.loc, total, diags);
            return;
        }
    }
}

}  // namespace glimmer
