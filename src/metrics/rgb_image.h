// A picture as doubles, for measuring: what the CPU references compute in
// and what metrics.h compares. Kept apart from any reference so the measures
// (grading, tradeoff, health) need no blur.
#pragma once
#include <cstddef>
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

}  // namespace glimmer
