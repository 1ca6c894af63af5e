#include "bloom/superblur_reference.h"

#include <algorithm>
#include <cmath>

namespace glimmer {

RgbImage superblurReference(const RgbImage& in, int uHalfSize) {
    const int h = uHalfSize | 1;  // the shader's "be sure it's an odd number"
    const double maxDistance = std::hypot(double(h), double(h)) + 1.0;
    RgbImage out = in;
    auto wrap = [](int v, int n) { return ((v % n) + n) % n; };
    for (int y = 0; y < in.height; ++y) {
        for (int x = 0; x < in.width; ++x) {
            double sum[3] = {0, 0, 0}, weightSum = 0;
            // The shader's i runs along s (x) and j along t; t grows upwards,
            // rows downwards, but the kernel is symmetric so the sign is moot.
            for (int i = -h; i <= h; ++i) {
                for (int j = -h; j <= h; ++j) {
                    double w = maxDistance - std::hypot(double(i), double(j));
                    int sx = wrap(x + i, in.width), sy = wrap(y + j, in.height);
                    for (int c = 0; c < 3; ++c) sum[c] += w * in.at(sx, sy, c);
                    weightSum += w;
                }
            }
            for (int c = 0; c < 3; ++c) out.rgb[(size_t(y) * size_t(in.width) + size_t(x)) * 3 + size_t(c)] = sum[c] / weightSum;
        }
    }
    return out;
}

RgbImage bloomReference(const RgbImage& image, const RgbImage& blur, double uAdd) {
    RgbImage out = image;
    for (size_t i = 0; i < out.rgb.size(); ++i) out.rgb[i] = image.rgb[i] + uAdd * blur.rgb[i];
    return out;
}

Image quantizeToRgba8(const RgbImage& in) {
    Image out = Image::rgba8(in.width, in.height);
    for (size_t i = 0; i < size_t(in.width) * size_t(in.height); ++i) {
        for (size_t c = 0; c < 3; ++c)
            out.u8[i * 4 + c] = std::uint8_t(std::lround(std::clamp(in.rgb[i * 3 + c], 0.0, 1.0) * 255.0));
        out.u8[i * 4 + 3] = 255;
    }
    return out;
}

}  // namespace glimmer
