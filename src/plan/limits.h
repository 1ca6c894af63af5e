// Every bound the planner and the loaders enforce, in one place, so a
// grader can read what an untrusted script may ask for
// (docs/RELIABILITY.md lists them).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "geometry/shape_registry.h"
#include "lang/diagnostics.h"
#include "lang/script.h"

namespace glimmer {

constexpr std::size_t kMaxScriptBytes = std::size_t(16) << 20;  // 16 MiB of .glib
constexpr std::size_t kMaxShaderBytes = std::size_t(4) << 20;   // 4 MiB a shader file
constexpr std::size_t kMaxPasses = 1000;                        // RenderToTexture passes
constexpr std::size_t kMaxDraws = 100000;                       // draws in the whole script
// Shapes: kMaxSubdivisions (1000 slices, stacks, rings, subdivisions) and
// kMaxTeapotSubdivisions (300), in geometry/shape_registry.h with their rows.
constexpr double kMaxShapeCount = kMaxSubdivisions;

// The default --max-memory, in MiB: what textures and targets may take on
// the GPU (and their copies on the CPU) together.
constexpr std::uint64_t kDefaultMaxMemoryMiB = 2048;

// A number of the script as an int when it is a whole number in [lo, hi];
// else false, and nothing is converted (no float-to-int overflow).
bool wholeIn(double v, double lo, double hi);

// Finite and at most 1e30 either way: safe to convert to float.
bool inFloatRange(double v);

// `v` converted to int, clamped to the int range first (never undefined).
int clampToInt(double v);

// `v` converted to float, clamped to the float range first (NaN stays NaN).
float clampToFloat(double v);

}  // namespace glimmer
