// SSIM against a case worked by hand, and the properties grading leans on.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/ssim.h"

namespace glimmer {
namespace {

TEST(Ssim, IdenticalPicturesScoreOne) {
    std::vector<double> a = {0.1, 0.5, 0.9, 0.3, 0.2, 0.7, 0.4, 0.6, 0.8};
    EXPECT_DOUBLE_EQ(ssim(a, a, 3, 3, 2), 1.0);
}

// One 2x2 window. a = {0, 0, 1, 1}, b = {0, 1, 0, 1}:
//   means 0.5 and 0.5; variances 0.25 and 0.25; covariance
//   ((-.5)(-.5) + (-.5)(.5) + (.5)(-.5) + (.5)(.5)) / 4 = 0.
//   SSIM = (2*.25 + C1)(0 + C2) / ((.25 + .25 + C1)(.25 + .25 + C2))
//        = (0.5001)(0.0009) / ((0.5001)(0.5009)) = 0.0009 / 0.5009
TEST(Ssim, MatchesACaseWorkedByHand) {
    std::vector<double> a = {0, 0, 1, 1}, b = {0, 1, 0, 1};
    EXPECT_NEAR(ssim(a, b, 2, 2, 2), 0.0009 / 0.5009, 1e-12);
    // b inverted: covariance -0.25: (0.5001)(-0.5 + 0.0009) / ((0.5001)(0.5009))
    std::vector<double> c = {1, 1, 0, 0};
    EXPECT_NEAR(ssim(a, c, 2, 2, 2), (-0.5 + 0.0009) / 0.5009, 1e-12);
}

TEST(Ssim, ABlankPictureScoresLowAgainstAPattern) {
    std::vector<double> pattern, blank(64, 0.0);
    for (int i = 0; i < 64; ++i) pattern.push_back(((i % 8) + (i / 8)) % 2);
    EXPECT_LT(ssim(pattern, blank, 8, 8), 0.01);
}

TEST(Ssim, SizeMismatchIsNaN) {
    std::vector<double> a(4, 0.0), b(3, 0.0);
    EXPECT_TRUE(std::isnan(ssim(a, b, 2, 2)));
}

}  // namespace
}  // namespace glimmer
