// Timings of repeated runs, and which method is fastest beyond their noise.
// `glimmer tradeoff` used to name the method with the lowest median as the
// winner; with a few runs on a shared machine that name changed from run to
// run. A winner is named here only when its slowest run is faster than every
// other candidate's fastest run; otherwise the methods that overlap it tie.
#pragma once
#include <string>
#include <vector>

namespace glimmer {

// Median, fastest and slowest of the timed runs (all 0 when there are none).
struct TimingSpread {
    double median = 0, min = 0, max = 0;
    int runs = 0;
};
TimingSpread spreadOf(std::vector<double> times);

struct TimedCandidate {
    std::string name;
    TimingSpread time;
};

// names: empty when there are no candidates; one name: a winner separated
// from every other candidate by more than the spread of the runs; several
// names: the candidate with the lowest median first, then every candidate
// whose fastest run is not slower than that one's slowest run (a tie within
// noise), by median.
struct FastestVerdict {
    std::vector<std::string> names;
    bool clearWinner() const { return names.size() == 1; }
};
FastestVerdict fastestBeyondNoise(const std::vector<TimedCandidate>& candidates);

}  // namespace glimmer
