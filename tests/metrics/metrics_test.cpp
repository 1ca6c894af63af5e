// ErrorStats and Health on inputs whose answers are known by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "metrics/metrics.h"

using namespace glimmer;

TEST(Metrics, UniformDifferenceOfOneHundredthIsFortyDecibels) {
    const RgbImage a(8, 5, 0.5), b(8, 5, 0.51);
    const ErrorStats s = compare(a, b);
    EXPECT_NEAR(s.psnr, 40.0, 1e-9);
    EXPECT_NEAR(s.rmse, 0.01, 1e-14);
    EXPECT_NEAR(s.maxAbs, 0.01, 1e-14);
    EXPECT_EQ(s.pixelsOverOneStep, 40u);  // 0.01 > 1/255 everywhere
}

TEST(Metrics, IdenticalImagesHaveInfinitePsnr) {
    const RgbImage a(4, 3, 0.25);
    const ErrorStats s = compare(a, a);
    EXPECT_TRUE(std::isinf(s.psnr) && s.psnr > 0);
    EXPECT_EQ(s.rmse, 0.0);
    EXPECT_EQ(s.maxAbs, 0.0);
    EXPECT_EQ(s.pixelsOverOneStep, 0u);
}

// One channel of one texel of a 2x2 off by 0.5: mse = 0.25 / 12.
TEST(Metrics, OneBadChannel) {
    RgbImage a(2, 2, 0.2), b(2, 2, 0.2);
    b.at(1, 1, 2) = 0.7;
    const ErrorStats s = compare(a, b);
    EXPECT_NEAR(s.rmse, std::sqrt(0.25 / 12), 1e-15);
    EXPECT_NEAR(s.psnr, 10 * std::log10(48.0), 1e-12);
    EXPECT_NEAR(s.maxAbs, 0.5, 1e-15);
    EXPECT_EQ(s.pixelsOverOneStep, 1u);
}

// "Over one step" is strictly more than 1/255 in some channel.
TEST(Metrics, OneStepThreshold) {
    RgbImage a(3, 1, 0.0), b(3, 1, 0.0);
    b.at(0, 0, 0) = 1.0 / 255.0;          // exactly one step: not over
    b.at(1, 0, 1) = 1.0001 / 255.0;       // over
    b.at(2, 0, 2) = -1.5 / 255.0;         // over, by absolute value
    EXPECT_EQ(compare(a, b).pixelsOverOneStep, 2u);
}

TEST(Metrics, SizeMismatchIsNaN) {
    const ErrorStats s = compare(RgbImage(2, 2), RgbImage(2, 3));
    EXPECT_TRUE(std::isnan(s.rmse) && std::isnan(s.psnr) && std::isnan(s.maxAbs));
    EXPECT_EQ(s.pixelsOverOneStep, 6u);
}

TEST(Metrics, HealthCountsACraftedBuffer) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    // 3 x 2 texels, RGBA, row by row.
    const std::vector<float> buf = {
        0.5f, 0.5f, 0.5f, 1.0f,        1.0f, 0.2f, nan, 1.0f,       0.0f, -0.0f, 65504.0f, 1.0f,  // row 0
        -1.0f, 0.1f, 0.1f, 1.0f,       70000.0f, inf, -inf, 0.0f,   1.0f, 0.99999994f, 2.0f, 0.3f,  // row 1
    };
    const Health h = healthOf(buf.data(), 3, 2);
    EXPECT_EQ(h.nan, 1u);
    EXPECT_EQ(h.inf, 2u);
    EXPECT_EQ(h.negative, 1u);     // -1; -0 is not negative, -Inf counts as Inf
    EXPECT_EQ(h.above65504, 1u);   // 70000; 65504 itself fits a half float
    EXPECT_EQ(h.clippedAtOne, 6u);  // exactly 1.0 only (4 alphas, 2 reds), not 0.99999994 or 2
    EXPECT_EQ(h.firstBadX, 1);      // the NaN, row 0
    EXPECT_EQ(h.firstBadY, 0);
    EXPECT_FALSE(h.healthy());

    const std::vector<float> good = {0.0f, 0.5f, 65504.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f};
    const Health g = healthOf(good.data(), 2, 1);
    EXPECT_TRUE(g.healthy());
    EXPECT_EQ(g.firstBadX, -1);
    EXPECT_EQ(g.firstBadY, -1);
    EXPECT_EQ(g.clippedAtOne, 1u);

    // The first bad texel in row order, on row 1.
    std::vector<float> late(4 * 4 * 3, 0.25f);
    late[(1 * 4 + 2) * 4 + 1] = -0.5f;
    late[(2 * 4 + 0) * 4 + 0] = nan;
    const Health l = healthOf(late.data(), 4, 3);
    EXPECT_EQ(l.firstBadX, 2);
    EXPECT_EQ(l.firstBadY, 1);
}
