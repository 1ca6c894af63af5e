// The planner's bounds and conversions (plan/limits.h), and MeshDecl::flat
// staying linear in its points.
#include <chrono>

#include <gtest/gtest.h>

#include "plan/limits.h"
#include "plan/plan.h"

namespace glimmer {
namespace {

TEST(PlanLimits, WholeInRefusesWhatWouldNotConvert) {
    EXPECT_TRUE(wholeIn(31, 0, 31));
    EXPECT_FALSE(wholeIn(1e24, 0, 31));
    EXPECT_FALSE(wholeIn(2.5, 0, 31));
    EXPECT_FALSE(wholeIn(std::numeric_limits<double>::quiet_NaN(), 0, 31));
    EXPECT_FALSE(wholeIn(std::numeric_limits<double>::infinity(), 0, 1e300));
}

TEST(PlanLimits, ClampsInsteadOfOverflowing) {
    EXPECT_EQ(clampToInt(1e24), 2147483647);
    EXPECT_EQ(clampToInt(-1e24), -2147483647 - 1);
    EXPECT_EQ(clampToInt(std::numeric_limits<double>::quiet_NaN()), 0);
    EXPECT_EQ(clampToInt(-7.9), -7);
    EXPECT_EQ(clampToFloat(1e300), std::numeric_limits<float>::max());
    EXPECT_EQ(clampToFloat(-1e300), -std::numeric_limits<float>::max());
    EXPECT_FALSE(inFloatRange(1e31));
    EXPECT_TRUE(inFloatRange(-1e30));
}

// Many points on one spot, then two that span a plane: a search over pairs
// of points tries every pair of the repeated ones first.
MeshDecl pointsDecl(size_t n, bool bumpLast) {
    MeshDecl m;
    m.shape = CommandKind::GlBegin;
    m.points.assign(n * 3, 0.0);
    m.points.insert(m.points.end(), {1.0, 1.0, 0.0, 0.0, 5.0, 0.0});
    if (bumpLast) m.points.insert(m.points.end(), {1.0, 1.0, 3.0});  // leaves the plane
    return m;
}

TEST(PlanLimits, FlatIsRightAndLinearOnManyRepeatedPoints) {
    auto t0 = std::chrono::steady_clock::now();
    EXPECT_TRUE(pointsDecl(48000, false).flat());
    EXPECT_FALSE(pointsDecl(48000, true).flat());
    // The search over pairs took seconds here.
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::milliseconds(500));
}

}  // namespace
}  // namespace glimmer
