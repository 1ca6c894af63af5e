#include "plan/limits.h"

#include <cmath>
#include <limits>

namespace glimmer {

bool wholeIn(double v, double lo, double hi) { return std::isfinite(v) && v == std::floor(v) && v >= lo && v <= hi; }

bool inFloatRange(double v) { return std::isfinite(v) && std::abs(v) <= 1e30; }

int clampToInt(double v) {
    if (std::isnan(v)) return 0;
    if (v <= double(std::numeric_limits<int>::min())) return std::numeric_limits<int>::min();
    if (v >= double(std::numeric_limits<int>::max())) return std::numeric_limits<int>::max();
    return int(v);
}

float clampToFloat(double v) {
    constexpr double hi = double(std::numeric_limits<float>::max());
    if (std::isnan(v)) return std::numeric_limits<float>::quiet_NaN();
    return float(v < -hi ? -hi : v > hi ? hi : v);
}

}  // namespace glimmer
