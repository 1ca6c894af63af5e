// A time-versus-error scatter chart with its Pareto front, drawn on the CPU
// into an RGBA8 Image, for `glimmer tradeoff`. Deterministic: the same
// points give the same bytes (for one font file; image/ttf_text.h).
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "image/image.h"

namespace glimmer {

struct ChartPoint {
    std::string label;
    double timeMs = 0;  // the median of the runs: where the dot goes
    double error = 0;   // PSNR in dB or RMSE, as ChartMetric says
    // The fastest and slowest run, drawn as a bar through the dot so the
    // reader sees how far apart two dots must be to differ; NaN: no bar.
    double timeMinMs = NAN, timeMaxMs = NAN;
};

// PsnrDb: higher is better, +inf (identical) drawn on the top edge with
// " (exact)" after its label. Rmse: lower is better. NaN points are skipped.
enum class ChartMetric { PsnrDb, Rmse };

// Where things go. Time runs along x on a log scale: methods differ by
// factors (5 ms against 200 ms), and equal ratios should look equally far
// apart. xMin..xMax are 1-2-5 values around every time (bars included), and
// xTicks the 1, 2 and 5 x 10^k values between them that get a number (only
// the powers of ten when the range spans more than three decades). Error
// runs linearly along y, yMin..yMax rounded out to "nice" steps of yStep.
// Row 0 is the top of the image.
struct ChartLayout {
    int width = 0, height = 0;
    int left = 0, top = 0, right = 0, bottom = 0;
    double xMin = 1, xMax = 10;
    std::vector<double> xTicks;
    double yMin = 0, yMax = 1, yStep = 1;
    int column(double timeMs) const;  // times <= 0 sit on the left edge
    int row(double error) const;      // clamped to the plot: +inf PSNR on the top edge
};

// `titleLines`: how many lines the title takes (split at '\n'); the plot
// starts below them.
ChartLayout paretoChartLayout(const std::vector<ChartPoint>& points, ChartMetric metric, int width = 800,
                              int height = 520, int titleLines = 1);

// Indices of the points on the Pareto front (no other point is both at least
// as fast and at least as good, and strictly better in one), fastest first.
std::vector<size_t> paretoFront(const std::vector<ChartPoint>& points, ChartMetric metric);

// Axes with numbered ticks, one dot per point (front dots orange
// (255,170,0), the others blue (80,160,255), radius 4) with its spread bar,
// the front joined by an orange line, and each dot's label in TrueType text
// placed where it covers no other label or dot (bloom/label_placement.h),
// with a leader line when it had to move away. The title may have several
// lines ('\n').
Image paretoChart(const std::vector<ChartPoint>& points, const std::string& title,
                  ChartMetric metric = ChartMetric::PsnrDb, int width = 800, int height = 520);

}  // namespace glimmer
