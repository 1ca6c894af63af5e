#include "pipeline/watch_picture.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace glimmer {

const WatchMarker kWatchMarkers[6] = {
    {WatchMark::NaN, 255, 0, 255, "NaN"},           {WatchMark::Inf, 255, 255, 0, "Inf"},
    {WatchMark::Below, 0, 160, 255, "below the range"}, {WatchMark::Above, 255, 96, 0, "above the range"},
    {WatchMark::NotReached, 96, 96, 160, "line not run"}, {WatchMark::NotDrawn, 64, 64, 64, "nothing drawn"},
};

namespace {

struct Pixel {
    const float* v;
    const float* info;
    bool drawn() const { return info[0] > 0.5f; }
    // The component count (the info is interpolated for a vertex watch, so rounded).
    int components() const { return drawn() ? std::clamp(int(std::lround(info[1])), 0, 4) : 0; }
    int kind() const { return std::clamp(int(std::lround(info[2])), 0, 3); }
};

bool sameShape(const Image& value, const Image& info) {
    const size_t n = size_t(value.width) * size_t(value.height) * 4;
    return value.width == info.width && value.height == info.height && value.f32.size() == n && info.f32.size() == n;
}

Pixel pixelAt(const Image& value, const Image& info, int x, int y) {
    size_t at = (size_t(y) * size_t(value.width) + size_t(x)) * 4;
    return {value.f32.data() + at, info.f32.data() + at};
}

// The mark of one pixel, NaN before Inf before the range.
WatchMark markOf(const Pixel& p, const WatchStats& s) {
    if (!p.drawn()) return WatchMark::NotDrawn;
    int n = p.components();
    if (n == 0) return WatchMark::NotReached;
    bool nan = false, inf = false, below = false, above = false;
    for (int c = 0; c < n; ++c) {
        nan |= std::isnan(p.v[c]);
        inf |= std::isinf(p.v[c]);
        below |= p.v[c] < float(s.range.lo);
        above |= p.v[c] > float(s.range.hi);
    }
    return nan ? WatchMark::NaN : inf ? WatchMark::Inf : below ? WatchMark::Below : above ? WatchMark::Above : WatchMark::None;
}

// As a GPU stores a float in an 8-bit channel: the product with 255 in float,
// rounded to nearest, ties to even (llvmpipe's 0.0647058859 * 255 = 16.5 gives
// 16; rounding the exact product up gave 17 and a byte unlike the shader's).
unsigned char toByte(float t) {
    const float product = std::clamp(t, 0.f, 1.f) * 255.f;
    return static_cast<unsigned char>(std::nearbyint(product));
}

std::string number(double v) { return fmt::format("{:.4g}", v); }

}  // namespace

std::string watchTypeName(int components, int kind) {
    static const char* const kScalar[] = {"float", "int", "uint", "bool"};
    static const char* const kPrefix[] = {"vec", "ivec", "uvec", "bvec"};
    kind = std::clamp(kind, 0, 3);
    if (components <= 1) return kScalar[kind];
    return std::string(kPrefix[kind]) + std::to_string(std::min(components, 4));
}

WatchStats watchStats(const Image& value, const Image& info, std::optional<WatchRange> fixed) {
    WatchStats s;
    if (!sameShape(value, info)) return s;
    s.width = value.width, s.height = value.height;
    s.lo.fill(std::numeric_limits<double>::infinity());
    s.hi.fill(-std::numeric_limits<double>::infinity());
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            Pixel p = pixelAt(value, info, x, y);
            if (!p.drawn()) continue;
            ++s.drawn;
            int n = p.components();
            if (n == 0) continue;
            ++s.reached;
            s.components = std::max(s.components, n);
            s.kind = p.kind();
            for (int c = 0; c < n; ++c) {
                if (!std::isfinite(p.v[c])) continue;
                s.lo[size_t(c)] = std::min(s.lo[size_t(c)], double(p.v[c]));
                s.hi[size_t(c)] = std::max(s.hi[size_t(c)], double(p.v[c]));
            }
        }
    s.fixed = fixed.has_value();
    s.range = watchRangeOf(s, fixed);
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) switch (markOf(pixelAt(value, info, x, y), s)) {
            case WatchMark::NaN: ++s.nan; break;
            case WatchMark::Inf: ++s.inf; break;
            case WatchMark::Below: ++s.below; break;
            case WatchMark::Above: ++s.above; break;
            default: break;
            }
    return s;
}

WatchRange watchRangeOf(const WatchStats& s, std::optional<WatchRange> fixed) {
    if (fixed) return *fixed;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int c = 0; c < s.components && c < 4; ++c) lo = std::min(lo, s.lo[size_t(c)]), hi = std::max(hi, s.hi[size_t(c)]);
    return lo <= hi ? WatchRange{lo, hi} : WatchRange{0, 1};
}

WatchMark watchMarkAt(const Image& value, const Image& info, const WatchStats& stats, int x, int y) {
    if (!sameShape(value, info) || x < 0 || y < 0 || x >= value.width || y >= value.height) return WatchMark::NotDrawn;
    return markOf(pixelAt(value, info, x, y), stats);
}

Image watchPicture(const Image& value, const Image& info, const WatchStats& s) {
    if (!sameShape(value, info)) return {};
    Image out = Image::rgba8(value.width, value.height);
    // In float, as the GPU's colouring pass (gl/watch_gpu.cpp) computes it.
    const float lo = float(s.range.lo), scale = watchScale(lo, float(s.range.hi));
    for (int y = 0; y < value.height; ++y)
        for (int x = 0; x < value.width; ++x) {
            Pixel p = pixelAt(value, info, x, y);
            unsigned char* o = out.u8.data() + (size_t(y) * size_t(value.width) + size_t(x)) * 4;
            WatchMark mark = markOf(p, s);
            if (mark != WatchMark::None) {
                const bool lit = ((x / 4) + (y / 4)) % 2 == 0;
                for (const WatchMarker& m : kWatchMarkers)
                    if (m.mark == mark) o[0] = lit ? m.r : 0, o[1] = lit ? m.g : 0, o[2] = lit ? m.b : 0;
                o[3] = 255;
                continue;
            }
            // A range of one value shows it as mid grey rather than dividing by zero.
            auto t = [&](int c) { return scale > 0 ? (p.v[c] - lo) * scale : 0.5f; };
            const int n = p.components();
            o[0] = toByte(t(0));
            o[1] = n >= 2 ? toByte(t(1)) : o[0];
            o[2] = n >= 3 ? toByte(t(2)) : n == 2 ? 0 : o[0];
            o[3] = n == 4 ? toByte(t(3)) : 255;
        }
    return out;
}

std::string watchSummary(const WatchStats& s) {
    if (s.components == 0)
        return fmt::format("the watched line ran at no pixel of the {}x{} pass ({} drawn)", s.width, s.height, s.drawn);
    std::string out = fmt::format("{} over {}x{}: range {} .. {} ({})", watchTypeName(s.components, s.kind), s.width,
                                  s.height, number(s.range.lo), number(s.range.hi), s.fixed ? "fixed" : "its own");
    static const char* const kNames[] = {"x", "y", "z", "w"};
    if (s.components > 1)
        for (int c = 0; c < s.components; ++c)
            out += s.lo[size_t(c)] <= s.hi[size_t(c)]
                       ? fmt::format("{} {} {} .. {}", c ? "," : ";", kNames[c], number(s.lo[size_t(c)]), number(s.hi[size_t(c)]))
                       : fmt::format("{} {} no finite value", c ? "," : ";", kNames[c]);
    const std::pair<long long, const char*> counts[] = {
        {s.nan, "NaN"}, {s.inf, "Inf"}, {s.below, "below the range"}, {s.above, "above the range"},
        {s.drawn - s.reached, "where the line did not run"}};
    for (const auto& [n, what] : counts)
        if (n) out += fmt::format("; {} pixel{} {}", n, n == 1 ? "" : "s", what);
    return out;
}

std::string watchValueAt(const Image& value, const Image& info, int x, int y) {
    if (!sameShape(value, info) || x < 0 || y < 0 || x >= value.width || y >= value.height) return "outside the pass";
    Pixel p = pixelAt(value, info, x, y);
    if (!p.drawn()) return "nothing drawn here";
    const int n = p.components();
    if (n == 0) return "the line did not run here";
    std::string out = watchTypeName(n, p.kind()) + (n > 1 ? "(" : " ");
    for (int c = 0; c < n; ++c) out += fmt::format("{}{:.9g}", c ? ", " : "", p.v[c]);
    return out + (n > 1 ? ")" : "");
}

}  // namespace glimmer
