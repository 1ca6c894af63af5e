#include "bloom/pareto_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "image/ttf_text.h"
#include "bloom/label_placement.h"

namespace glimmer {
namespace {

struct Rgb8 {
    std::uint8_t r, g, b;
};
constexpr Rgb8 kBackground{20, 20, 24}, kAxis{200, 200, 200}, kGrid{48, 48, 56}, kGridMinor{32, 32, 38};
constexpr Rgb8 kFront{255, 170, 0}, kOther{80, 160, 255};
constexpr Rgb8 kFrontBar{170, 115, 20}, kOtherBar{60, 110, 170};
constexpr TextColor kText{230, 230, 230}, kFrontText{255, 205, 130}, kOtherText{170, 205, 255};
constexpr int kDotRadius = 4;
// Pixel heights of the text: the title, axis names and point labels, tick numbers.
constexpr float kTitlePx = 17, kLabelPx = 13, kTickPx = 12;

bool usable(const ChartPoint& p, ChartMetric metric) {
    if (std::isnan(p.timeMs) || std::isnan(p.error) || std::isinf(p.timeMs)) return false;
    return !std::isinf(p.error) || (metric == ChartMetric::PsnrDb && p.error > 0);
}

bool hasBar(const ChartPoint& p) {
    return std::isfinite(p.timeMinMs) && std::isfinite(p.timeMaxMs) && p.timeMaxMs > p.timeMinMs;
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

// The 1-2-5 values: 1, 2, 5, 10, 20, ... as (mantissa, exponent) steps.
double oneTwoFive(int k) {
    static const double m[3] = {1, 2, 5};
    const int e = int(std::floor(k / 3.0));
    return m[k - 3 * e] * std::pow(10.0, e);
}
// The index of the largest 1-2-5 value <= v (v > 0).
int oneTwoFiveBelow(double v) {
    int k = 3 * int(std::floor(std::log10(v))) - 3;
    while (oneTwoFive(k + 1) <= v * (1 + 1e-12)) ++k;
    return k;
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

// A label's box darkens what is under it (the front's line, grid lines), so
// the text reads on anything.
void darken(Image& img, const PixelBox& b) {
    for (int y = std::max(b.y, 0); y < std::min(b.y + b.h, img.height); ++y)
        for (int x = std::max(b.x, 0); x < std::min(b.x + b.w, img.width); ++x) {
            std::uint8_t* p = &img.u8[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
            p[0] = std::uint8_t(p[0] / 3), p[1] = std::uint8_t(p[1] / 3), p[2] = std::uint8_t(p[2] / 3);
        }
}

std::string number(double v, double step) {
    v = std::round(v / step) * step;
    if (std::fabs(v) < step * 1e-9) v = 0;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> out(1);
    for (char c : text)
        if (c == '\n') out.emplace_back();
        else out.back() += c;
    return out;
}

// A label's text padding inside its box.
constexpr int kPad = 2;

}  // namespace

int ChartLayout::column(double t) const {
    const double lo = std::log10(xMin), hi = std::log10(xMax);
    const double v = t > 0 ? std::clamp(std::log10(t), lo, hi) : lo;
    return left + int(std::lround((v - lo) / (hi - lo) * (right - left)));
}

int ChartLayout::row(double y) const {
    y = std::clamp(y, yMin, yMax);
    return bottom - int(std::lround((y - yMin) / (yMax - yMin) * (bottom - top)));
}

ChartLayout paretoChartLayout(const std::vector<ChartPoint>& points, ChartMetric metric, int width, int height,
                              int titleLines) {
    ChartLayout l;
    l.width = width, l.height = height;
    const int lineH = labelLineHeight(kTitlePx);
    l.left = 70, l.right = width - 30, l.top = 14 + titleLines * lineH + labelLineHeight(kLabelPx) + 10;
    l.bottom = height - 2 * labelLineHeight(kLabelPx) - 20;
    double tLo = INFINITY, tHi = 0, eLo = 0, eHi = 0;
    bool any = false;
    for (const ChartPoint& p : points) {
        if (!usable(p, metric)) continue;
        for (double t : {p.timeMs, p.timeMinMs, p.timeMaxMs})
            if (t > 0 && std::isfinite(t)) tLo = std::min(tLo, t), tHi = std::max(tHi, t);
        if (std::isinf(p.error)) continue;
        eLo = any ? std::min(eLo, p.error) : p.error;
        eHi = any ? std::max(eHi, p.error) : p.error;
        any = true;
    }
    if (!(tHi > 0)) tLo = tHi = 1;  // no positive time: a decade around 1 ms
    int kLo = oneTwoFiveBelow(tLo), kHi = oneTwoFiveBelow(tHi);
    if (oneTwoFive(kHi) < tHi * (1 - 1e-12)) ++kHi;
    while (kHi - kLo < 3) --kLo, ++kHi;  // at least a decade and a bit: one value never fills the axis
    l.xMin = oneTwoFive(kLo), l.xMax = oneTwoFive(kHi);
    const bool decadesOnly = kHi - kLo > 9;  // more than three decades: 2 and 5 would crowd
    for (int k = kLo; k <= kHi; ++k)
        if (!decadesOnly || k % 3 == 0) l.xTicks.push_back(oneTwoFive(k));
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
    const std::vector<std::string> titleLines = splitLines(title);
    const ChartLayout l = paretoChartLayout(points, metric, width, height, int(titleLines.size()));
    Image img = Image::rgba8(width, height);
    for (size_t i = 0; i < img.u8.size(); i += 4)
        img.u8[i] = kBackground.r, img.u8[i + 1] = kBackground.g, img.u8[i + 2] = kBackground.b, img.u8[i + 3] = 255;

    // Grid: faint lines at 1..9 x 10^k, brighter at the numbered ticks.
    for (double d = std::pow(10.0, std::floor(std::log10(l.xMin))); d <= l.xMax; d *= 10)
        for (int m = 1; m <= 9; ++m)
            if (d * m >= l.xMin && d * m <= l.xMax) line(img, l.column(d * m), l.top, l.column(d * m), l.bottom, kGridMinor);
    const int tickH = labelLineHeight(kTickPx);
    for (double v : l.xTicks) {
        const int x = l.column(v);
        line(img, x, l.top, x, l.bottom, kGrid);
        line(img, x, l.bottom, x, l.bottom + 5, kAxis);
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", v);
        drawLabel(img, x - labelWidth(buf, kTickPx) / 2, l.bottom + 7, buf, kTickPx, kText);
    }
    const int yTicks = int(std::lround((l.yMax - l.yMin) / l.yStep));
    for (int k = 0; k <= yTicks; ++k) {
        const double v = l.yMin + k * l.yStep;
        const int y = l.row(v);
        line(img, l.left, y, l.right, y, kGrid);
        line(img, l.left - 5, y, l.left, y, kAxis);
        const std::string s = number(v, l.yStep);
        drawLabel(img, l.left - 8 - labelWidth(s, kTickPx), y - tickH / 2, s, kTickPx, kText);
    }
    line(img, l.left, l.top, l.left, l.bottom, kAxis);
    line(img, l.left, l.bottom, l.right, l.bottom, kAxis);
    for (size_t i = 0; i < titleLines.size(); ++i)
        drawLabel(img, 10, 8 + int(i) * labelLineHeight(kTitlePx), titleLines[i], kTitlePx, kText);
    const bool anyBar = std::any_of(points.begin(), points.end(), [&](const ChartPoint& p) { return usable(p, metric) && hasBar(p); });
    const std::string xName = anyBar ? "time (ms, log scale): dot = median, bar = fastest to slowest run"
                                     : "time (ms, log scale)";
    drawLabel(img, (l.left + l.right - labelWidth(xName, kLabelPx)) / 2, l.bottom + 9 + tickH, xName, kLabelPx, kText);
    drawLabel(img, l.left + 4, l.top - labelLineHeight(kLabelPx) - 6,
              metric == ChartMetric::PsnrDb ? "PSNR (dB), higher is better" : "RMSE, lower is better", kLabelPx, kText);

    const std::vector<size_t> front = paretoFront(points, metric);
    auto onFront = [&](size_t i) { return std::find(front.begin(), front.end(), i) != front.end(); };

    // Spread bars (with end caps), under the front's line and the dots.
    std::vector<PixelBox> bars;  // and other things labels must not cover
    for (size_t i = 0; i < points.size(); ++i) {
        const ChartPoint& p = points[i];
        if (!usable(p, metric) || !hasBar(p)) continue;
        const int x0 = l.column(p.timeMinMs), x1 = l.column(p.timeMaxMs), y = l.row(p.error);
        const Rgb8 c = onFront(i) ? kFrontBar : kOtherBar;
        line(img, x0, y, x1, y, c);
        line(img, x0, y - 3, x0, y + 3, c);
        line(img, x1, y - 3, x1, y + 3, c);
        bars.push_back({x0, y - 3, x1 - x0 + 1, 7});
    }
    for (size_t k = 1; k < front.size(); ++k) {
        const ChartPoint &a = points[front[k - 1]], &b = points[front[k]];
        line(img, l.column(a.timeMs), l.row(a.error), l.column(b.timeMs), l.row(b.error), kFront);
    }

    // The front's line is an obstacle too (as small squares along it): a
    // label's box over it would hide the part of the front the chart is about.
    for (size_t k = 1; k < front.size(); ++k) {
        const int x0 = l.column(points[front[k - 1]].timeMs), y0 = l.row(points[front[k - 1]].error);
        const int x1 = l.column(points[front[k]].timeMs), y1 = l.row(points[front[k]].error);
        const int steps = std::max(1, int(std::hypot(x1 - x0, y1 - y0) / 4));
        for (int s = 0; s <= steps; ++s)
            bars.push_back({x0 + (x1 - x0) * s / steps - 1, y0 + (y1 - y0) * s / steps - 1, 3, 3});
    }

    // Labels: placed clear of each other, the dots, the bars and the front, inside the plot.
    std::vector<size_t> shown;
    std::vector<LabelRequest> requests;
    std::vector<std::string> texts;
    const int labelH = labelLineHeight(kLabelPx) + 2 * kPad;
    for (size_t i = 0; i < points.size(); ++i) {
        const ChartPoint& p = points[i];
        if (!usable(p, metric)) continue;
        texts.push_back(std::isinf(p.error) ? p.label + " (exact)" : p.label);
        requests.push_back({l.column(p.timeMs), l.row(p.error), labelWidth(texts.back(), kLabelPx) + 2 * kPad, labelH});
        shown.push_back(i);
    }
    const PixelBox plot{l.left + 1, l.top, l.right - l.left, l.bottom - l.top};
    const std::vector<PlacedLabel> placed = placeLabels(requests, plot, kDotRadius, bars);
    for (size_t k = 0; k < placed.size(); ++k) {
        const PixelBox& b = placed[k].box;
        const bool f = onFront(shown[k]);
        if (placed[k].leader) {
            // From the dot's edge to the nearest point of the box.
            const int bx = std::clamp(requests[k].x, b.x, b.x + b.w - 1), by = std::clamp(requests[k].y, b.y, b.y + b.h - 1);
            const double d = std::hypot(bx - requests[k].x, by - requests[k].y);
            const int sx = requests[k].x + int(std::lround((bx - requests[k].x) * (kDotRadius + 1) / d));
            const int sy = requests[k].y + int(std::lround((by - requests[k].y) * (kDotRadius + 1) / d));
            line(img, sx, sy, bx, by, f ? kFrontBar : kOtherBar);
        }
        darken(img, b);
        drawLabel(img, b.x + kPad, b.y + kPad, texts[k], kLabelPx, f ? kFrontText : kOtherText);
    }

    // The dots on top of everything.
    for (size_t i = 0; i < points.size(); ++i)
        if (usable(points[i], metric))
            disc(img, l.column(points[i].timeMs), l.row(points[i].error), kDotRadius, onFront(i) ? kFront : kOther);
    return img;
}

}  // namespace glimmer
