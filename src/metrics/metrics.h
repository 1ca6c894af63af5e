// How far a GPU blur is from its CPU reference, and whether a float target
// holds anything a later pass would choke on. For `glimmer tradeoff`.
#pragma once
#include <cstddef>

#include "metrics/rgb_image.h"

namespace glimmer {

// Differences over the three channels of every texel of two same-sized
// images (values as stored, no clamping).
struct ErrorStats {
    double rmse = 0;                    // sqrt(mean of squared differences)
    double psnr = 0;                    // 10 log10(1 / mse), peak 1.0, in dB; +inf when identical
    double maxAbs = 0;                  // largest |difference|
    std::size_t pixelsOverOneStep = 0;  // texels with |difference| > 1/255 in any channel
};

// a and b must have the same size; a size mismatch returns rmse = maxAbs =
// psnr = NaN and every texel counted.
ErrorStats compare(const RgbImage& a, const RgbImage& b);

// Counts over every float (all four channels) of an RGBA float buffer of
// width x height texels, rows in buffer order.
struct Health {
    std::size_t nan = 0;
    std::size_t inf = 0;           // +Inf and -Inf
    std::size_t negative = 0;      // finite and < 0 (-0 is not negative)
    std::size_t above65504 = 0;    // finite and > 65504, the largest half float (Inf in RGBA16F)
    std::size_t clippedAtOne = 0;  // exactly 1.0: what a clamp or an RGBA8 target leaves at the top
    int firstBadX = -1, firstBadY = -1;  // first texel (row by row) with a NaN, Inf, negative or
                                         // > 65504 value; -1, -1 when none
    bool healthy() const { return nan == 0 && inf == 0 && negative == 0 && above65504 == 0; }
};

Health healthOf(const float* rgba, int width, int height);

}  // namespace glimmer
