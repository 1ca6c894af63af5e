// Small statistics the benchmarks and the tradeoff share.
#pragma once
#include <algorithm>
#include <vector>

namespace glimmer {

// The middle value (the mean of the two middle ones for an even count); 0
// for none. Timings are summarised by their median: one slow run (a page
// fault, another process) must not move the figure.
inline double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace glimmer
