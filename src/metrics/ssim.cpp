#include "metrics/ssim.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glimmer {

double ssim(const std::vector<double>& a, const std::vector<double>& b, int width, int height, int window) {
    const size_t texels = size_t(std::max(width, 0)) * size_t(std::max(height, 0));
    if (width <= 0 || height <= 0 || a.size() != texels || b.size() != texels)
        return std::numeric_limits<double>::quiet_NaN();
    const int wx = std::min(window, width), wy = std::min(window, height);
    const int stepX = std::max(1, wx / 2), stepY = std::max(1, wy / 2);
    const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
    double sum = 0;
    long count = 0;
    for (int y0 = 0; y0 + wy <= height; y0 += stepY) {
        for (int x0 = 0; x0 + wx <= width; x0 += stepX) {
            double ma = 0, mb = 0;
            for (int y = y0; y < y0 + wy; ++y)
                for (int x = x0; x < x0 + wx; ++x) {
                    ma += a[size_t(y) * size_t(width) + size_t(x)];
                    mb += b[size_t(y) * size_t(width) + size_t(x)];
                }
            const double n = double(wx) * double(wy);
            ma /= n;
            mb /= n;
            double va = 0, vb = 0, cov = 0;
            for (int y = y0; y < y0 + wy; ++y)
                for (int x = x0; x < x0 + wx; ++x) {
                    const double da = a[size_t(y) * size_t(width) + size_t(x)] - ma;
                    const double db = b[size_t(y) * size_t(width) + size_t(x)] - mb;
                    va += da * da;
                    vb += db * db;
                    cov += da * db;
                }
            va /= n;  // population variances, as the paper's formula is usually applied
            vb /= n;
            cov /= n;
            sum += ((2 * ma * mb + c1) * (2 * cov + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
            ++count;
        }
    }
    return count ? sum / double(count) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace glimmer
