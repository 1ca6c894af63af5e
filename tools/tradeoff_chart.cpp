// Redraws the chart of a `glimmer tradeoff` CSV without running the methods
// again: for a committed run taken on a machine not at hand (the H100 table
// in docs/bloom.md), so its picture is drawn like every new one. Reads the
// method, ms and model_psnr columns, and ms_min, ms_max where present (older
// CSVs lack them: no spread bars then).
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bloom/pareto_chart.h"

namespace {

std::vector<std::string> cells(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) out.push_back(c);
    return out;
}

int column(const std::vector<std::string>& header, const std::string& name) {
    for (size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return int(i);
    return -1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s TRADEOFF.csv OUT.png TITLE (\\n in TITLE starts a second line)\n", argv[0]);
        return 2;
    }
    std::ifstream in(argv[1]);
    std::string line;
    if (!std::getline(in, line)) {
        std::fprintf(stderr, "glimmer-tradeoff-chart: cannot read %s\n", argv[1]);
        return 1;
    }
    const std::vector<std::string> header = cells(line);
    const int name = column(header, "method"), ms = column(header, "ms"), psnr = column(header, "model_psnr");
    const int lo = column(header, "ms_min"), hi = column(header, "ms_max");
    if (name < 0 || ms < 0 || psnr < 0) {
        std::fprintf(stderr, "glimmer-tradeoff-chart: %s has no method, ms or model_psnr column\n", argv[1]);
        return 1;
    }
    std::vector<glimmer::ChartPoint> points;
    while (std::getline(in, line)) {
        const std::vector<std::string> c = cells(line);
        if (int(c.size()) <= std::max(ms, psnr)) continue;
        glimmer::ChartPoint p{c[size_t(name)], std::stod(c[size_t(ms)]), std::stod(c[size_t(psnr)])};
        if (lo >= 0 && hi >= 0 && int(c.size()) > std::max(lo, hi))
            p.timeMinMs = std::stod(c[size_t(lo)]), p.timeMaxMs = std::stod(c[size_t(hi)]);
        points.push_back(p);
    }
    std::string title;
    for (const char* c = argv[3]; *c; ++c) {
        if (c[0] == '\\' && c[1] == 'n') title += '\n', ++c;
        else title += *c;
    }
    std::string why;
    if (!glimmer::writePng(argv[2], glimmer::paretoChart(points, title), why)) {
        std::fprintf(stderr, "glimmer-tradeoff-chart: %s\n", why.c_str());
        return 1;
    }
    std::printf("wrote %s (%zu methods)\n", argv[2], points.size());
    return 0;
}
