// What `glimmer tradeoff` reports once every method has run: the printed
// table and verdict, the CSV and the JSON. Kept apart from the measuring so
// each file has one job; the chart is bloom/pareto_chart.h.
#pragma once
#include <string>
#include <vector>

#include "bloom/timing_verdict.h"
#include "bloom/tradeoff_run.h"  // TradeoffRow

namespace glimmer {

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
