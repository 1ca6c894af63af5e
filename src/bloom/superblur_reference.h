// An independent CPU reference, in double precision, of the seed's superblur
// and bloom shaders. Used by tests and benchmarks, never on the render path.
// It models the calibration scene: a quad exactly covering a target the size
// of the input, so fragment (x, y) samples the texel centre (x + i, y + j).
#pragma once
#include "image/image.h"
#include "metrics/rgb_image.h"

namespace glimmer {


// superblur.frag: a (2h+1)^2 box with h = uHalfSize | 1, weights
// maxDistance - |(i,j)| where maxDistance = |(h,h)| + 1, normalised. Texture
// lookups wrap (GL_REPEAT).
RgbImage superblurReference(const RgbImage& in, int uHalfSize);

// bloom.frag: image + uAdd * blur, as the shader computes it (not clamped).
RgbImage bloomReference(const RgbImage& image, const RgbImage& blur, double uAdd);

// What an RGBA8 target stores: clamp to [0,1], round to the nearest of 255 steps.
Image quantizeToRgba8(const RgbImage& in);

}  // namespace glimmer
