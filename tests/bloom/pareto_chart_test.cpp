// The chart is the same bytes every time, and its dots sit where its axes
// say they are.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "bloom/pareto_chart.h"

using namespace glimmer;

namespace {

const std::vector<ChartPoint> kPoints = {
    {"box", 0.5, 32.0}, {"gauss9", 1.2, 41.0}, {"cod", 3.1, 47.5}, {"kawase", 4.0, 45.0}};

bool pixelIs(const Image& img, int x, int y, int r, int g, int b) {
    const std::uint8_t* p = &img.u8[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
    return p[0] == r && p[1] == g && p[2] == b && p[3] == 255;
}

bool orangeNear(const Image& img, int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (pixelIs(img, x + dx, y + dy, 255, 170, 0)) return true;
    return false;
}

}  // namespace

TEST(ParetoChart, IsDeterministic) {
    const Image a = paretoChart(kPoints, "bloom lab"), b = paretoChart(kPoints, "bloom lab");
    ASSERT_EQ(a.width, 800);
    ASSERT_EQ(a.height, 520);
    EXPECT_EQ(a.u8, b.u8);
    std::vector<ChartPoint> moved = kPoints;
    moved[1].timeMs = 1.3;
    EXPECT_NE(paretoChart(moved, "bloom lab").u8, a.u8);
}

TEST(ParetoChart, FrontIsTheUndominatedPoints) {
    const std::vector<size_t> front = paretoFront(kPoints, ChartMetric::PsnrDb);
    EXPECT_EQ(front, (std::vector<size_t>{0, 1, 2}));  // kawase: slower and worse than cod
    // For RMSE lower is better: the same points read as RMSE flip the order.
    EXPECT_EQ(paretoFront(kPoints, ChartMetric::Rmse), (std::vector<size_t>{0}));
}

// Times 0.5..4.0 ms: a log axis from 0.5 to 5 with numbers at 0.5, 1, 2 and
// 5. PSNR 32..47.5 dB: ticks of 5 from 30 to 50. Each dot's centre is where
// those numbers put it.
TEST(ParetoChart, DotsSitWhereTheAxesSay) {
    const ChartLayout l = paretoChartLayout(kPoints, ChartMetric::PsnrDb);
    EXPECT_EQ(l.xMin, 0.5);
    EXPECT_EQ(l.xMax, 5.0);
    EXPECT_EQ(l.xTicks, (std::vector<double>{0.5, 1, 2, 5}));
    EXPECT_EQ(l.yMin, 30.0);
    EXPECT_EQ(l.yMax, 50.0);
    EXPECT_EQ(l.yStep, 5.0);
    const Image img = paretoChart(kPoints, "bloom lab");
    auto col = [&](double t) { return l.left + int(std::lround(std::log10(t / 0.5) * (l.right - l.left))); };
    auto row = [&](double db) { return l.bottom - int(std::lround((db - 30.0) / 20.0 * (l.bottom - l.top))); };
    EXPECT_EQ(l.column(1.0), col(1.0));
    EXPECT_EQ(l.column(1.0) - l.column(0.5), l.column(4.0) - l.column(2.0));  // equal ratios, equal distances
    for (size_t i = 0; i < 3; ++i)
        EXPECT_TRUE(pixelIs(img, col(kPoints[i].timeMs), row(kPoints[i].error), 255, 170, 0)) << kPoints[i].label;
    EXPECT_TRUE(pixelIs(img, col(4.0), row(45.0), 80, 160, 255));  // off the front: blue
    // Nothing at a place no point is.
    EXPECT_FALSE(pixelIs(img, col(2.0), row(35.0), 80, 160, 255));
    EXPECT_FALSE(pixelIs(img, col(2.0), row(35.0), 255, 170, 0));
    // The front's line passes through the midpoint of two front dots (a
    // straight line between them on the picture).
    EXPECT_TRUE(orangeNear(img, (col(1.2) + col(3.1)) / 2, (row(41.0) + row(47.5)) / 2));
    // The x axis and its tick at 2 ms.
    EXPECT_TRUE(pixelIs(img, col(2.0), l.bottom, 200, 200, 200));
    EXPECT_TRUE(pixelIs(img, col(2.0), l.bottom + 4, 200, 200, 200));
}

// Over more than three decades only the powers of ten are numbered.
TEST(ParetoChart, WideTimeRangesNumberDecadesOnly) {
    const ChartLayout l = paretoChartLayout({{"a", 0.03, 40}, {"b", 300, 50}}, ChartMetric::PsnrDb);
    EXPECT_EQ(l.xMin, 0.02);
    EXPECT_EQ(l.xMax, 500.0);
    EXPECT_EQ(l.xTicks, (std::vector<double>{0.1, 1, 10, 100}));
}

// The bar of the runs' spread runs from the fastest to the slowest run, in a
// darker shade of the dot's colour, and counts in the axis range.
TEST(ParetoChart, SpreadBarsSpanTheRuns) {
    std::vector<ChartPoint> pts = kPoints;
    pts[1].timeMinMs = 0.9, pts[1].timeMaxMs = 1.8;
    pts[3].timeMinMs = 3.5, pts[3].timeMaxMs = 9.0;  // beyond every median: widens the axis
    const ChartLayout l = paretoChartLayout(pts, ChartMetric::PsnrDb);
    EXPECT_EQ(l.xMax, 10.0);
    const Image img = paretoChart(pts, "spread");
    const int y = l.row(41.0);
    EXPECT_TRUE(pixelIs(img, l.column(0.95), y, 170, 115, 20));  // front bar, left of the dot
    EXPECT_TRUE(pixelIs(img, l.column(1.75), y, 170, 115, 20));  // and right of it
    EXPECT_FALSE(pixelIs(img, l.column(0.85), y, 170, 115, 20)); // not past the fastest run
    EXPECT_TRUE(pixelIs(img, l.column(8.8), l.row(45.0), 60, 110, 170));  // off the front: dark blue
}

// An exact method (+inf dB) sits on the top edge; NaN points are skipped.
TEST(ParetoChart, InfiniteAndNaNPoints) {
    std::vector<ChartPoint> pts = kPoints;
    pts.push_back({"exact", 2.0, std::numeric_limits<double>::infinity()});
    pts.push_back({"broken", 1.0, std::numeric_limits<double>::quiet_NaN()});
    const ChartLayout l = paretoChartLayout(pts, ChartMetric::PsnrDb);
    EXPECT_EQ(l.yMax, 50.0);  // the finite points set the range
    const Image img = paretoChart(pts, "with exact");
    EXPECT_TRUE(pixelIs(img, l.column(2.0), l.top, 255, 170, 0));  // on the front: nothing faster is better
    const std::vector<size_t> front = paretoFront(pts, ChartMetric::PsnrDb);
    EXPECT_EQ(front, (std::vector<size_t>{0, 1, 4}));
}

// A title of two lines pushes the plot down.
TEST(ParetoChart, TwoLineTitleMovesThePlot) {
    EXPECT_GT(paretoChartLayout(kPoints, ChartMetric::PsnrDb, 800, 520, 2).top,
              paretoChartLayout(kPoints, ChartMetric::PsnrDb, 800, 520, 1).top);
}

TEST(ParetoChart, EmptyAndSinglePointsDraw) {
    const Image empty = paretoChart({}, "nothing");
    EXPECT_EQ(empty.width, 800);
    const ChartLayout one = paretoChartLayout({{"only", 0.0, 30.0}}, ChartMetric::Rmse);
    EXPECT_LT(one.yMin, 30.0);
    EXPECT_GT(one.yMax, 30.0);
    EXPECT_GT(one.xMax, one.xMin);
    EXPECT_GT(one.xMin, 0.0);  // a log axis: a time of 0 sits on its left edge
    EXPECT_EQ(one.column(0.0), one.left);
    const Image img = paretoChart({{"only", 0.0, 30.0}}, "one", ChartMetric::Rmse);
    EXPECT_EQ(img.u8.size(), size_t(800 * 520 * 4));
}
