// An independent CPU reference, in double precision, of the seed's superblur
// and bloom shaders. Used by tests and benchmarks, never on the render path.
// It models the calibration scene: a quad exactly covering a target the size
// of the input, so fragment (x, y) samples the texel centre (x + i, y + j).
#pragma once
#include <vector>

#include "image/image.h"

namespace glimmer {

// RGB in [0,1] per texel, row 0 at the top, as doubles.
struct RgbImage {
    int width = 0, height = 0;
    std::vector<double> rgb;  // 3 per texel

    RgbImage() = default;
    // A w x h picture, every channel of every texel set to `value`.
    RgbImage(int w, int h, double value = 0.0)
        : width(w), height(h), rgb(size_t(w) * size_t(h) * 3, value) {}

    size_t index(int x, int y, int c) const { return (size_t(y) * size_t(width) + size_t(x)) * 3 + size_t(c); }
    double at(int x, int y, int c) const { return rgb[index(x, y, c)]; }
    double& at(int x, int y, int c) { return rgb[index(x, y, c)]; }
    // The same value in all three channels of texel (x, y).
    void set(int x, int y, double v) { rgb[index(x, y, 0)] = rgb[index(x, y, 1)] = rgb[index(x, y, 2)] = v; }
};

RgbImage toRgb(const Image& img);

// superblur.frag: a (2h+1)^2 box with h = uHalfSize | 1, weights
// maxDistance - |(i,j)| where maxDistance = |(h,h)| + 1, normalised. Texture
// lookups wrap (GL_REPEAT).
RgbImage superblurReference(const RgbImage& in, int uHalfSize);

// bloom.frag: image + uAdd * blur, as the shader computes it (not clamped).
RgbImage bloomReference(const RgbImage& image, const RgbImage& blur, double uAdd);

// What an RGBA8 target stores: clamp to [0,1], round to the nearest of 255 steps.
Image quantizeToRgba8(const RgbImage& in);

}  // namespace glimmer
