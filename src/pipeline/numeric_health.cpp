#include "pipeline/numeric_health.h"

#include <cmath>

#include <fmt/format.h>

namespace glimmer {
namespace {

Health healthOfImage(const Image& img) {
    if (img.type == Image::Type::F32) return healthOf(img.f32.data(), img.width, img.height);
    std::vector<float> f(img.u8.size());
    // Alpha is 1 everywhere in an 8-bit target; only colour counts as clipped.
    for (size_t i = 0; i < f.size(); ++i) f[i] = i % 4 == 3 ? 0.f : img.u8[i] / 255.f;
    return healthOf(f.data(), img.width, img.height);
}

}  // namespace

std::vector<TargetHealth> measureHealth(const Renderer& r, const Plan& plan) {
    std::vector<TargetHealth> out;
    for (int t : r.renderTargets()) {
        const TextureDecl& decl = plan.textures[size_t(t)];
        std::string units;
        for (const auto& [unit, tex] : plan.finalUnits)
            if (tex == t) units += (units.empty() ? "unit " : ",") + std::to_string(unit);
        if (units.empty()) units = fmt::format("texture (line {})", decl.loc.line);
        TargetHealth h;
        h.eightBit = !isFloatFormat(decl.format);
        h.name = fmt::format("{} ({} {}x{})", units, textureFormatName(decl.format), decl.width, decl.height);
        Image img = h.eightBit ? r.readTexture(t) : r.readTextureFloat(t);
        h.health = healthOfImage(img);
        // A half-float target saturates: a value that was larger reads back
        // as exactly 65504 (or Inf, depending on the driver). Count it too.
        if (decl.format == TextureDecl::Format::RGBA16F)
            for (size_t i = 0; i < img.f32.size(); ++i)
                if (i % 4 != 3 && std::fabs(img.f32[i]) == 65504.f) ++h.health.above65504;
        out.push_back(h);
    }
    if (plan.screenNeeded()) {
        TargetHealth h;
        h.eightBit = true;
        h.name = fmt::format("screen (RGBA8 {}x{})", plan.width, plan.height);
        h.health = healthOfImage(r.readScreen());
        out.push_back(h);
    }
    return out;
}

std::string formatHealth(const TargetHealth& t) {
    const Health& h = t.health;
    std::string s = fmt::format("health: {}: {} NaN, {} Inf, {} negative, {} above 65504", t.name, h.nan, h.inf,
                                h.negative, h.above65504);
    // In an 8-bit target a 1 may be a value that was brighter: count them.
    if (t.eightBit) s += fmt::format(", {} at 1 (clipped if brighter)", h.clippedAtOne);
    if (t.bad()) s += fmt::format("; first bad pixel at {},{}", h.firstBadX, h.firstBadY);
    return s;
}

}  // namespace glimmer
