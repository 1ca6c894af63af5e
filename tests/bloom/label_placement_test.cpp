// Labels of a crowded chart: no two overlap, none covers a dot, all inside.
#include <gtest/gtest.h>

#include "bloom/label_placement.h"

using namespace glimmer;

namespace {

const PixelBox kBounds{0, 0, 800, 520};
constexpr int kDot = 4;

PixelBox dotBox(const LabelRequest& l) { return {l.x - kDot, l.y - kDot, 2 * kDot + 1, 2 * kDot + 1}; }

}  // namespace

TEST(LabelPlacement, OverlapIsSharedPixels) {
    EXPECT_TRUE(boxesOverlap({0, 0, 10, 10}, {9, 9, 5, 5}));
    EXPECT_FALSE(boxesOverlap({0, 0, 10, 10}, {10, 0, 5, 5}));     // touching edges share no pixel
    EXPECT_TRUE(boxesOverlap({0, 0, 10, 10}, {11, 0, 5, 5}, 2));   // but come within the margin
}

TEST(LabelPlacement, LoneLabelSitsRightOfItsDot) {
    const auto placed = placeLabels({{100, 100, 60, 14}}, kBounds, kDot);
    ASSERT_EQ(placed.size(), 1u);
    EXPECT_FALSE(placed[0].leader);
    EXPECT_TRUE(placed[0].free);
    EXPECT_GT(placed[0].box.x, 100 + kDot);
    EXPECT_LT(placed[0].box.x, 100 + kDot + 10);
    EXPECT_EQ(placed[0].box.y, 100 - 7);
}

TEST(LabelPlacement, AtTheRightEdgeTheLabelGoesLeft) {
    const auto placed = placeLabels({{795, 100, 60, 14}}, kBounds, kDot);
    EXPECT_LT(placed[0].box.x + placed[0].box.w, 795 - kDot);
    EXPECT_FALSE(placed[0].leader);
}

// Twenty points in a 60 x 40 pixel cluster with labels of up to 110 pixels:
// the places next to most dots are taken, so most labels move out with a
// leader line, and still none overlaps another or a dot.
TEST(LabelPlacement, CrowdedPointsGetNoOverlaps) {
    std::vector<LabelRequest> req;
    for (int i = 0; i < 20; ++i) req.push_back({400 + (i * 37) % 60, 300 + (i * 23) % 40, 50 + (i * 13) % 60, 14});
    const PixelBox bar{380, 330, 120, 3};  // an obstacle such as a spread bar
    const auto placed = placeLabels(req, kBounds, kDot, {bar});
    ASSERT_EQ(placed.size(), req.size());
    int leaders = 0;
    for (size_t i = 0; i < placed.size(); ++i) {
        const PixelBox& a = placed[i].box;
        EXPECT_TRUE(placed[i].free) << i;
        EXPECT_EQ(a.w, req[i].w);
        EXPECT_GE(a.x, 0);
        EXPECT_GE(a.y, 0);
        EXPECT_LE(a.x + a.w, kBounds.w);
        EXPECT_LE(a.y + a.h, kBounds.h);
        EXPECT_FALSE(boxesOverlap(a, bar)) << i;
        for (size_t j = 0; j < req.size(); ++j) {
            EXPECT_FALSE(boxesOverlap(a, dotBox(req[j]))) << "label " << i << " covers dot " << j;
            if (j != i) {
                EXPECT_FALSE(boxesOverlap(a, placed[j].box)) << "labels " << i << " and " << j;
            }
        }
        leaders += placed[i].leader;
    }
    EXPECT_GT(leaders, 5);  // the crowd really was crowded
}

TEST(LabelPlacement, NoRoomAnywhereIsReportedNotHidden) {
    // Two labels wider than half of a tiny chart: the second cannot be free.
    const auto placed = placeLabels({{20, 10, 30, 10}, {25, 10, 30, 10}}, {0, 0, 40, 30}, 2);
    EXPECT_TRUE(placed[0].free);
    EXPECT_FALSE(placed[1].free);
    EXPECT_LE(placed[1].box.x + placed[1].box.w, 40);
}
