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
std::uint64_t mib(std::uint64_t b) { return (b + (1u << 20) - 1) >> 20; }
std::uint64_t screenBytes(const Plan& plan) {
    return std::uint64_t(plan.width) * std::uint64_t(plan.height) * 8;  // colour and depth
}
}  // namespace

std::uint64_t plannedBytes(const Plan& plan) {
    std::uint64_t total = screenBytes(plan);
    for (const auto& t : plan.textures) total += textureBytes(t);
    return total;
}

void reportOverBudget(const Plan& plan, SourceLoc loc, std::uint64_t total, Diagnostics& diags) {
    diags.error(plan.scriptFile, loc,
                fmt::format("textures and render targets need {} MiB by this line, more than the memory "
                            "budget of {} MiB (--max-memory)", mib(total), plan.maxMemoryBytes >> 20));
}

void checkMemoryBudget(const Plan& plan, std::uint64_t budget, Diagnostics& diags) {
    std::uint64_t total = screenBytes(plan);
    for (const auto& t : plan.textures) {
        total += textureBytes(t);
        if (total > budget) {
            reportOverBudget(plan, t.loc, total, diags);
            return;
        }
    }
}

}  // namespace glimmer
