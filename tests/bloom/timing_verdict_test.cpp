// A winner is named only when the runs separate it from the rest.
#include <gtest/gtest.h>

#include "bloom/timing_verdict.h"

using namespace glimmer;

namespace {

TimedCandidate cand(const std::string& name, std::vector<double> runs) { return {name, spreadOf(std::move(runs))}; }

}  // namespace

TEST(TimingSpread, MedianMinMax) {
    const TimingSpread odd = spreadOf({5.0, 1.0, 3.0});
    EXPECT_EQ(odd.median, 3.0);
    EXPECT_EQ(odd.min, 1.0);
    EXPECT_EQ(odd.max, 5.0);
    EXPECT_EQ(odd.runs, 3);
    EXPECT_EQ(spreadOf({4.0, 1.0, 2.0, 10.0}).median, 3.0);  // even count: mean of the middle two
    EXPECT_EQ(spreadOf({}).runs, 0);
}

TEST(FastestVerdict, ClearWinnerWhenItsSlowestRunBeatsEveryFastestRun) {
    const FastestVerdict v = fastestBeyondNoise(
        {cand("slow", {9.0, 9.5, 10.0}), cand("fast", {4.0, 4.4, 4.9}), cand("mid", {5.0, 5.2, 7.0})});
    ASSERT_TRUE(v.clearWinner());
    EXPECT_EQ(v.names[0], "fast");
}

TEST(FastestVerdict, OverlappingSpreadsTie) {
    // b's median is lower, but a's fastest run is faster than b's slowest.
    const FastestVerdict v =
        fastestBeyondNoise({cand("a", {5.0, 5.5, 6.0}), cand("b", {4.0, 5.2, 5.6}), cand("c", {5.7, 8.0, 9.0})});
    EXPECT_FALSE(v.clearWinner());
    EXPECT_EQ(v.names, (std::vector<std::string>{"b", "a"}));  // c's fastest 5.7 > b's slowest 5.6: not tied
}

TEST(FastestVerdict, TouchingSpreadsTie) {
    const FastestVerdict v = fastestBeyondNoise({cand("a", {3.0}), cand("b", {3.0})});
    EXPECT_EQ(v.names.size(), 2u);
}

TEST(FastestVerdict, OneCandidateWinsAlone) {
    const FastestVerdict v = fastestBeyondNoise({cand("only", {2.0, 8.0})});
    ASSERT_TRUE(v.clearWinner());
    EXPECT_EQ(v.names[0], "only");
}

TEST(FastestVerdict, NoCandidatesNoName) { EXPECT_TRUE(fastestBeyondNoise({}).names.empty()); }
