// What `glimmer tradeoff` reports once every method has run: the printed
// table and verdict, the CSV and the JSON. Kept apart from the measuring so
// each file has one job; the chart is bloom/pareto_chart.h.
#pragma once
#include <string>
#include <vector>

#include "bloom/blur_methods.h"
#include "metrics/metrics.h"
#include "bloom/timing_verdict.h"

namespace glimmer {

struct TradeoffRow {
    const BlurMethod* method = nullptr;
    double ms = 0;      // the median run
    TimingSpread time;  // every run: median, fastest, slowest
    double sigma = 0;   // the method's own impulse sigma (achieved, under --match-sigma)
    double megabytes = 0;
    // The texel-rate floor for the method's taps: taps per pixel times the
    // hand-written probe's time per tap (Renderer::texelRateMs: its fastest
    // run; same run, format and size); 0 when the probe could not run. The
    // table's min/flr compares the method's fastest run with it: on a shared
    // GPU, only the fastest runs are free of other work.
    double floorMs = 0;
    ErrorStats numerical, model;
    Health health;  // of the blurred target: NaN, Inf, negative, above 65504
};

void printTradeoffTable(const std::vector<TradeoffRow>& rows);

// Among the methods within 40 dB PSNR of their Gaussian: a winner only when
// its runs separate it from the rest, else the tie (bloom/timing_verdict.h),
// and a note when `repeat` is too few runs to show the noise.
FastestVerdict printTradeoffVerdict(const std::vector<TradeoffRow>& rows, int repeat);

// matchSigma: the --match-sigma target, 0 at natural width. New CSV columns
// go after the old ones, so readers that count columns keep working.
void writeTradeoffCsv(const std::string& path, const std::vector<TradeoffRow>& rows, double matchSigma);
void writeTradeoffJson(const std::string& path, const std::string& title, const std::vector<TradeoffRow>& rows,
                       const FastestVerdict& verdict, double matchSigma);

}  // namespace glimmer
