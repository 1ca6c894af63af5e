// A time-versus-error scatter chart with its Pareto front, drawn on the CPU
// into an RGBA8 Image, for `glimmer tradeoff`. Deterministic: the same
// points give the same bytes.
#pragma once
#include <string>
#include <vector>

#include "image/image.h"

namespace glimmer {

struct ChartPoint {
    std::string label;
    double timeMs = 0;
    double error = 0;  // PSNR in dB or RMSE, as ChartMetric says
};

// PsnrDb: higher is better, +inf (identical) drawn on the top edge with
// " (exact)" after its label. Rmse: lower is better. NaN points are skipped.
enum class ChartMetric { PsnrDb, Rmse };

// Where things go: data (xMin..xMax, yMin..yMax) maps linearly onto the plot
// rectangle, x = time to columns left..right, y = error to rows bottom..top
// (row 0 at the top of the image). Ranges are rounded out to "nice" tick
// steps (1, 2 or 5 x 10^k); time starts at 0.
struct ChartLayout {
    int width = 0, height = 0;
    int left = 0, top = 0, right = 0, bottom = 0;
    double xMin = 0, xMax = 1, xStep = 1;
    double yMin = 0, yMax = 1, yStep = 1;
};

ChartLayout paretoChartLayout(const std::vector<ChartPoint>& points, ChartMetric metric, int width = 800,
                              int height = 520);

// Indices of the points on the Pareto front (no other point is both at least
// as fast and at least as good, and strictly better in one), fastest first.
std::vector<size_t> paretoFront(const std::vector<ChartPoint>& points, ChartMetric metric);

// Axes with numbered ticks, one dot per point (front dots orange
// (255,170,0), the others blue (80,160,255), radius 4), each labelled with
// drawText, and the front joined by an orange line.
Image paretoChart(const std::vector<ChartPoint>& points, const std::string& title,
                  ChartMetric metric = ChartMetric::PsnrDb, int width = 800, int height = 520);

}  // namespace glimmer
