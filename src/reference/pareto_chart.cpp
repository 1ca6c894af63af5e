#include "reference/pareto_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>

#include "image/text.h"

namespace glimmer {
namespace {

struct Rgb8 {
    std::uint8_t r, g, b;
};
constexpr Rgb8 kBackground{20, 20, 24}, kAxis{200, 200, 200}, kGrid{48, 48, 56};
constexpr Rgb8 kFront{255, 170, 0}, kOther{80, 160, 255};
constexpr int kDotRadius = 4;

bool usable(const ChartPoint& p, ChartMetric metric) {
    if (std::isnan(p.timeMs) || std::isnan(p.error) || std::isinf(p.timeMs)) return false;
    return !std::isinf(p.error) || (metric == ChartMetric::PsnrDb && p.error > 0);
}

// "Goodness" along y: larger is better for both metrics.
double quality(const ChartPoint& p, ChartMetric metric) { return metric == ChartMetric::PsnrDb ? p.error : -p.error; }

double niceStep(double span) {
    if (!(span > 0)) return 1.0;
    const double raw = span / 5.0;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / mag;
    return (f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 5.0 ? 5.0 : 10.0) * mag;
}

void niceRange(double lo, double hi, double& outLo, double& outHi, double& step) {
    if (!(hi > lo)) {  // one value, or none: a unit range around it
        const double pad = lo == 0 ? 1.0 : std::fabs(lo) * 0.1;
        lo -= pad, hi += pad;
    }
    step = niceStep(hi - lo);
    outLo = std::floor(lo / step) * step;
    outHi = std::ceil(hi / step) * step;
    if (!(outHi > outLo)) outHi = outLo + step;
}

void put(Image& img, int x, int y, Rgb8 c) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
    std::uint8_t* p = &img.u8[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
    p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 255;
}

// Bresenham.
void line(Image& img, int x0, int y0, int x1, int y1, Rgb8 c) {
    const int dx = std::abs(x1 - x0), sx = x0 < x1 ? 1 : -1;
    const int dy = -std::abs(y1 - y0), sy = y0 < y1 ? 1 : -1;
    int err = dx + dy;
    for (;;) {
        put(img, x0, y0, c);
        if (x0 == x1 && y0 == y1) break;
        const int e2 = 2 * err;
        if (e2 >= dy) err += dy, x0 += sx;
        if (e2 <= dx) err += dx, y0 += sy;
    }
}

void disc(Image& img, int cx, int cy, int r, Rgb8 c) {
    for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x)
            if (x * x + y * y <= r * r) put(img, cx + x, cy + y, c);
}

std::string number(double v, double step) {
    v = std::round(v / step) * step;
    if (std::fabs(v) < step * 1e-9) v = 0;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

int toColumn(const ChartLayout& l, double x) {
    return l.left + int(std::lround((x - l.xMin) / (l.xMax - l.xMin) * (l.right - l.left)));
}
int toRow(const ChartLayout& l, double y) {
    y = std::clamp(y, l.yMin, l.yMax);  // +inf PSNR sits on the top edge
    return l.bottom - int(std::lround((y - l.yMin) / (l.yMax - l.yMin) * (l.bottom - l.top)));
}

}  // namespace

ChartLayout paretoChartLayout(const std::vector<ChartPoint>& points, ChartMetric metric, int width, int height) {
    ChartLayout l;
    l.width = width, l.height = height;
    l.left = 70, l.right = width - 30, l.top = 60, l.bottom = height - 50;
    double tMax = 0, eLo = 0, eHi = 0;
    bool any = false;
    for (const ChartPoint& p : points) {
        if (!usable(p, metric)) continue;
        tMax = std::max(tMax, p.timeMs);
        if (std::isinf(p.error)) continue;
        eLo = any ? std::min(eLo, p.error) : p.error;
        eHi = any ? std::max(eHi, p.error) : p.error;
        any = true;
    }
    double unused = 0;
    niceRange(0.0, tMax, unused, l.xMax, l.xStep);
    l.xMin = 0;
    niceRange(eLo, eHi, l.yMin, l.yMax, l.yStep);
    return l;
}

// Sort by time, then best first; a point is on the front when it beats the
// best quality of every point no slower than it.
std::vector<size_t> paretoFront(const std::vector<ChartPoint>& points, ChartMetric metric) {
    std::vector<size_t> order;
    for (size_t i = 0; i < points.size(); ++i)
        if (usable(points[i], metric)) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (points[a].timeMs != points[b].timeMs) return points[a].timeMs < points[b].timeMs;
        return quality(points[a], metric) > quality(points[b], metric);
    });
    std::vector<size_t> front;
    for (size_t i : order)
        if (front.empty() || quality(points[i], metric) > quality(points[front.back()], metric)) front.push_back(i);
    return front;
}

Image paretoChart(const std::vector<ChartPoint>& points, const std::string& title, ChartMetric metric, int width,
                  int height) {
    const ChartLayout l = paretoChartLayout(points, metric, width, height);
    Image img = Image::rgba8(width, height);
    for (size_t i = 0; i < img.u8.size(); i += 4)
        img.u8[i] = kBackground.r, img.u8[i + 1] = kBackground.g, img.u8[i + 2] = kBackground.b, img.u8[i + 3] = 255;

    // Grid, ticks and their numbers.
    const int xTicks = int(std::lround((l.xMax - l.xMin) / l.xStep));
    for (int k = 0; k <= xTicks; ++k) {
        const double v = l.xMin + k * l.xStep;
        const int x = toColumn(l, v);
        line(img, x, l.top, x, l.bottom, kGrid);
        line(img, x, l.bottom, x, l.bottom + 5, kAxis);
        const std::string s = number(v, l.xStep);
        int tw = 0, th = 0;
        measureText(s, 1, tw, th);
        drawText(img, x - tw / 2, l.bottom + 7, s, 1);
    }
    const int yTicks = int(std::lround((l.yMax - l.yMin) / l.yStep));
    for (int k = 0; k <= yTicks; ++k) {
        const double v = l.yMin + k * l.yStep;
        const int y = toRow(l, v);
        line(img, l.left, y, l.right, y, kGrid);
        line(img, l.left - 5, y, l.left, y, kAxis);
        const std::string s = number(v, l.yStep);
        int tw = 0, th = 0;
        measureText(s, 1, tw, th);
        drawText(img, l.left - 7 - tw, y - th / 2, s, 1);
    }
    line(img, l.left, l.top, l.left, l.bottom, kAxis);
    line(img, l.left, l.bottom, l.right, l.bottom, kAxis);
    drawText(img, 10, 10, title, 2);
    drawText(img, (l.left + l.right) / 2 - 30, height - 22, "time (ms)", 1);
    drawText(img, l.left + 4, l.top - 18,
             metric == ChartMetric::PsnrDb ? "PSNR (dB), higher is better" : "RMSE, lower is better", 1);

    // Labels, then the front's line, then the dots on top of everything.
    const std::vector<size_t> front = paretoFront(points, metric);
    for (const ChartPoint& p : points) {
        if (!usable(p, metric)) continue;
        const std::string text = std::isinf(p.error) ? p.label + " (exact)" : p.label;
        int tw = 0, th = 0;
        measureText(text, 1, tw, th);
        const int x = toColumn(l, p.timeMs);
        // Right of the dot, or left of it where the label would leave the image.
        const int tx = x + kDotRadius + 3 + tw <= width ? x + kDotRadius + 3 : x - kDotRadius - 3 - tw;
        drawText(img, tx, toRow(l, p.error) - 14, text, 1);
    }
    for (size_t k = 1; k < front.size(); ++k) {
        const ChartPoint &a = points[front[k - 1]], &b = points[front[k]];
        line(img, toColumn(l, a.timeMs), toRow(l, a.error), toColumn(l, b.timeMs), toRow(l, b.error), kFront);
    }
    for (size_t i = 0; i < points.size(); ++i) {
        if (!usable(points[i], metric)) continue;
        const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
        disc(img, toColumn(l, points[i].timeMs), toRow(l, points[i].error), kDotRadius, onFront ? kFront : kOther);
    }
    return img;
}

}  // namespace glimmer
