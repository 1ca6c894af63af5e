// The numeric health of every target a script rendered: NaN, Inf, negative
// values, values above 65504 (the largest half float), and values at 1 in
// 8-bit targets (where anything brighter was clipped). For graders
// (`render --strict`) and for students looking at an HDR pipeline.
#pragma once
#include <string>
#include <vector>

#include "gl/renderer.h"
#include "metrics/metrics.h"

namespace glimmer {

struct TargetHealth {
    std::string name;  // "unit 6 (RGBA16F 512x512)" or "screen (RGBA8 512x512)"
    Health health;
    bool eightBit = false;
    bool bad() const { return health.nan || health.inf || health.negative || health.above65504; }
};

std::vector<TargetHealth> measureHealth(const Renderer& r, const Plan& plan);
std::string formatHealth(const TargetHealth& h);

}  // namespace glimmer
