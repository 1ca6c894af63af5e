// --max-memory: what the textures and render targets a plan declares will
// take, checked before anything is allocated.
#pragma once
#include <cstdint>

#include "lang/diagnostics.h"
#include "plan/plan.h"

namespace glimmer {

// Bytes one texture takes on the GPU: empty 2-D textures and targets in
// their format (a third more with mips, 4 bytes a texel more with depth),
// empty 3-D textures as RGBA8. Image files count 0 here: each is bounded by
// the image limits (image/sniff.h) when it is read.
std::uint64_t textureBytes(const TextureDecl& t);

// Bytes a built-in noise texture of `dims` (2 or 3) and resolution `res`
// takes while it is made and once uploaded.
std::uint64_t noiseBytes(int dims, int res);

// Adds up the screen and every texture in script order; the first texture
// that takes the total past `budget` is an error on its line.
void checkMemoryBudget(const Plan& plan, std::uint64_t budget, Diagnostics& diags);

// What the plan declares (the screen and every empty texture and target):
// the image files the load step decodes are added to this (assets/).
std::uint64_t plannedBytes(const Plan& plan);

// The error for a budget passed at `loc`.
void reportOverBudget(const Plan& plan, SourceLoc loc, std::uint64_t total, Diagnostics& diags);

}  // namespace glimmer
