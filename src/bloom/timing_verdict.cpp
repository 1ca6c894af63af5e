#include "bloom/timing_verdict.h"

#include <algorithm>

namespace glimmer {

TimingSpread spreadOf(std::vector<double> times) {
    TimingSpread s;
    if (times.empty()) return s;
    std::sort(times.begin(), times.end());
    const size_t n = times.size();
    s.runs = int(n);
    s.min = times.front();
    s.max = times.back();
    s.median = n % 2 ? times[n / 2] : (times[n / 2 - 1] + times[n / 2]) / 2;
    return s;
}

FastestVerdict fastestBeyondNoise(const std::vector<TimedCandidate>& candidates) {
    FastestVerdict v;
    if (candidates.empty()) return v;
    std::vector<const TimedCandidate*> byMedian;
    for (const auto& c : candidates) byMedian.push_back(&c);
    std::stable_sort(byMedian.begin(), byMedian.end(),
                     [](const TimedCandidate* a, const TimedCandidate* b) { return a->time.median < b->time.median; });
    const TimedCandidate& best = *byMedian.front();
    v.names.push_back(best.name);
    // Overlapping [min, max] ranges: the runs cannot tell these apart. Equal
    // values overlap too (one run each, same time: no winner).
    for (size_t i = 1; i < byMedian.size(); ++i)
        if (byMedian[i]->time.min <= best.time.max) v.names.push_back(byMedian[i]->name);
    return v;
}

}  // namespace glimmer
