#include "app/tradeoff_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "util/json.h"
#include "util/write_file.h"

namespace glimmer {
void printTradeoffTable(const std::vector<TradeoffRow>& rows) {
    fmt::print("{:<16}{:>6}{:>9}{:>9}{:>9}{:>9}{:>8}{:>10}{:>8} | {:>10}{:>9}{:>10}{:>9} | {:>10}{:>9}{:>10}{:>9} | {:>6}\n",
               "method", "taps", "ms", "min", "max", "floor", "min/flr", "MB moved", "sigma", "num RMSE", "num PSNR",
               "num max", "num >1st", "mod RMSE", "mod PSNR", "mod max", "mod >1st", "health");
    for (const auto& r : rows)
        fmt::print("{:<16}{:>6}{:>9.2f}{:>9.2f}{:>9.2f}{:>9.2f}{:>8.2f}{:>10.1f}{:>8.2f} | {:>10.2e}{:>9.1f}{:>10.2e}{:>9} | "
                   "{:>10.2e}{:>9.1f}{:>10.2e}{:>9} | {:>6}\n",
                   r.method->name, r.method->tapsPerPixel, r.ms, r.time.min, r.time.max, r.floorMs,
                   r.floorMs > 0 ? r.time.min / r.floorMs : 0.0, r.megabytes, r.sigma,
                   r.numerical.rmse, r.numerical.psnr, r.numerical.maxAbs, r.numerical.pixelsOverOneStep,
                   r.model.rmse, r.model.psnr, r.model.maxAbs, r.model.pixelsOverOneStep,
                   r.health.healthy() ? "ok" : "BAD");
}

FastestVerdict printTradeoffVerdict(const std::vector<TradeoffRow>& rows, int repeat) {
    const std::vector<TimedCandidate> candidates = nearGaussianCandidates(rows);
    const FastestVerdict verdict = fastestBeyondNoise(candidates);
    const char* within = "within 40 dB PSNR of the Gaussian of its own sigma";
    if (verdict.names.empty()) {
        fmt::print("no method came {}\n", within);
    } else if (verdict.clearWinner()) {
        const TradeoffRow& w = *std::find_if(rows.begin(), rows.end(),
                                             [&](const TradeoffRow& r) { return r.method->name == verdict.names[0]; });
        fmt::print("fastest {}: {} ({:.2f} ms, runs {:.2f} to {:.2f}, {:.1f} dB){}\n", within, w.method->name, w.ms,
                   w.time.min, w.time.max, w.model.psnr,
                   candidates.size() > 1 ? "; its slowest run beats every other candidate's fastest" : "");
    } else {
        fmt::print("fastest {}: tie within noise: {} (their fastest to slowest runs overlap)\n", within,
                   fmt::join(verdict.names, ", "));
    }
    if (repeat < 3 && !candidates.empty())
        fmt::print("note: {} run{} per method cannot show the noise; --repeat 5 or more for a verdict to trust\n",
                   repeat, repeat == 1 ? "" : "s");
    return verdict;
}

void writeTradeoffCsv(const std::string& path, const std::vector<TradeoffRow>& rows, double matchSigma) {
    std::ostringstream csv;  // written whole at the end (util/write_file.h)
    csv << "method,family,taps,passes,ms,megabytes,sigma,num_rmse,num_psnr,num_max,num_over_one_step,model_rmse,"
           "model_psnr,model_max,model_over_one_step,nan,inf,negative,above_65504,ms_min,ms_max,runs,target_sigma,"
           "floor_ms\n";
    for (const auto& r : rows)
        csv << fmt::format("{},{},{},{},{:.4f},{:.2f},{:.4f},{:.6g},{:.3f},{:.6g},{},{:.6g},{:.3f},{:.6g},{},{},{},{},{},"
                           "{:.4f},{:.4f},{},{},{:.6g}\n",
                           r.method->name, r.method->family, r.method->tapsPerPixel, r.method->passes, r.ms,
                           r.megabytes, r.sigma, r.numerical.rmse, r.numerical.psnr, r.numerical.maxAbs,
                           r.numerical.pixelsOverOneStep, r.model.rmse, r.model.psnr, r.model.maxAbs,
                           r.model.pixelsOverOneStep, r.health.nan, r.health.inf, r.health.negative,
                           r.health.above65504, r.time.min, r.time.max, r.time.runs,
                           matchSigma > 0 ? fmt::format("{:g}", matchSigma) : "", r.floorMs);
    std::string error, text = csv.str();
    writeBytesReplacing(path, text.data(), text.size(), error);
}

void writeTradeoffJson(const std::string& path, const std::string& title, const std::vector<TradeoffRow>& rows,
                       const FastestVerdict& verdict, double matchSigma) {
    auto number = [](double v) { return jsonNumber(v, 6); };  // measurements: 6 digits, as the CSV
    Json json;
    json["title"] = title;
    json["comparison"] = matchSigma > 0 ? Json{{"matched_sigma", number(matchSigma)}} : Json("natural width");
    json["fastest_within_40db"] = {{"clear_winner", verdict.clearWinner()}, {"methods", verdict.names}};
    json["methods"] = Json::array();
    auto errors = [&](const ErrorStats& e) {
        return Json{{"rmse", number(e.rmse)}, {"psnr", number(e.psnr)}, {"max", number(e.maxAbs)},
                    {"over_one_step", e.pixelsOverOneStep}};
    };
    for (const TradeoffRow& r : rows) {
        Json m;
        m["method"] = r.method->name;
        m["family"] = r.method->family;
        m["taps"] = r.method->tapsPerPixel;
        m["passes"] = r.method->passes;
        m["ms"] = number(r.ms);
        m["ms_min"] = number(r.time.min);
        m["ms_max"] = number(r.time.max);
        m["runs"] = r.time.runs;
        m["floor_ms"] = number(r.floorMs);
        m["megabytes"] = number(r.megabytes);
        m["sigma"] = number(r.sigma);
        m["numerical"] = errors(r.numerical);
        m["model"] = errors(r.model);
        m["health"] = {{"nan", r.health.nan}, {"inf", r.health.inf}, {"negative", r.health.negative},
                       {"above_65504", r.health.above65504}};
        json["methods"].push_back(m);
    }
    std::string error, text = jsonDocument(json);
    writeBytesReplacing(path, text.data(), text.size(), error);
}

}  // namespace glimmer
