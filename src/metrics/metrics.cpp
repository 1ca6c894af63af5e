#include "metrics/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glimmer {

ErrorStats compare(const RgbImage& a, const RgbImage& b) {
    ErrorStats s;
    const std::size_t texels = std::size_t(a.width) * std::size_t(a.height);
    if (a.width != b.width || a.height != b.height || a.rgb.size() != b.rgb.size()) {
        s.rmse = s.psnr = s.maxAbs = std::numeric_limits<double>::quiet_NaN();
        s.pixelsOverOneStep = std::max(texels, std::size_t(b.width) * std::size_t(b.height));
        return s;
    }
    double sum = 0;
    for (std::size_t t = 0; t < texels; ++t) {
        bool over = false;
        for (std::size_t c = 0; c < 3; ++c) {
            const double d = std::fabs(a.rgb[t * 3 + c] - b.rgb[t * 3 + c]);
            sum += d * d;
            if (d > s.maxAbs || std::isnan(d)) s.maxAbs = d;
            over = over || !(d <= 1.0 / 255.0);  // NaN counts as over
        }
        s.pixelsOverOneStep += over;
    }
    const double mse = texels ? sum / double(texels * 3) : 0.0;
    s.rmse = std::sqrt(mse);
    s.psnr = mse == 0 ? std::numeric_limits<double>::infinity() : -10.0 * std::log10(mse);
    return s;
}

Health healthOf(const float* rgba, int width, int height) {
    Health h;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            bool bad = false;
            for (int c = 0; c < 4; ++c) {
                const float v = rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4 + std::size_t(c)];
                if (std::isnan(v)) {
                    ++h.nan, bad = true;
                } else if (std::isinf(v)) {
                    ++h.inf, bad = true;
                } else {
                    if (v < 0) ++h.negative, bad = true;
                    if (v > 65504.0f) ++h.above65504, bad = true;
                    if (v == 1.0f) ++h.clippedAtOne;
                }
            }
            if (bad && h.firstBadX < 0) h.firstBadX = x, h.firstBadY = y;
        }
    }
    return h;
}

}  // namespace glimmer
