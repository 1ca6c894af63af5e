// Pictures the project generates itself for its scripts and tests.
#pragma once
#include "image/image.h"

namespace glimmer {

// The seed bloom's input: a dark background with thin bright grid lines and
// a few coloured squares, so both the blur and the glow show. Deterministic.
Image makeGridImage(int width, int height);

// Deterministic pseudo-random RGBA8 noise (every channel independent), for
// pixel tests where every texel differs from its neighbours.
Image makeNoiseImage(int width, int height, unsigned seed);

}  // namespace glimmer
