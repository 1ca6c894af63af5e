// The Newell teapot ("Utah teapot") as published by Martin Newell (1975) and
// reproduced in Frank Crow, "The Origins of the Teapot", IEEE CG&A 7(1), 1987:
// 32 bicubic Bezier patches over 306 control points, Z up, spout towards +X.
// The tables follow the published listing: control points numbered from 1.
#pragma once
#include <cstdint>

namespace glimmer::teapot {

inline constexpr int kNumVertices = 306;
inline constexpr int kNumPatches = 32;

// Control points (x, y, z); kVertices[k - 1] is the published point k.
extern const float kVertices[kNumVertices][3];
// Each patch: 4 rows of 4 control point numbers (1-based), row-major.
// Going along a row then down the rows is counter-clockwise seen from outside.
extern const std::uint16_t kPatches[kNumPatches][16];

// Patch groups in the published order (0-based patch numbers).
inline constexpr int kRim = 0, kBody = 4, kHandle = 12, kSpout = 16, kLid = 20, kBottom = 28;

}  // namespace glimmer::teapot
