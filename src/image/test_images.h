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

// The bloom lab's HDR input, in the seed's spirit: a dark ground (about
// 0.02 to 0.06), bright emitters from 1.5 to 15 (discs and bars), and one
// tiny spot of 1000 that makes fireflies in careless blurs. RGBA float,
// alpha 1. Deterministic.
Image makeHdrScene(int width, int height);

}  // namespace glimmer
