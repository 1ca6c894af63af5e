// What a watch's floats say (issue 28): their range, how many pixels hold
// NaN, Inf or values outside a fixed range, and the picture that shows them.
// No OpenGL: it reads the two float images gl/renderer.h's WatchCapture holds.
// The GPU computes the same numbers and picture without reading the floats
// back (gl/watch_gpu.cpp); this is the reference the tests hold it to, and
// what a probe of one pixel says.
//
// The picture, per pixel where the watched line ran: t = (v - lo) x s per
// component, s = watchScale(lo, hi), in float with lo and hi as floats (as
// the GPU draws it, gl/watch_gpu.cpp; below and above are against those
// floats too), as 8 bits rounded as a GPU stores a colour (t x 255 in float,
// to nearest, ties to even):
// a scalar grey (t, t, t, 1), a vec2 (t0, t1, 0, 1), a vec3 (t0, t1, t2, 1),
// a vec4 (t0, t1, t2, t3). So a value in 0..1 watched with range 0,1 gives
// the bytes of a shader that writes that value as its colour. Elsewhere a
// 4-pixel checker of a marker colour and black (kWatchMarkers): a pixel with
// a NaN, an Inf, a value below or above the range, a fragment where the
// line did not run, no fragment at all.
#pragma once
#include <array>
#include <limits>
#include <optional>
#include <string>

#include "image/image.h"

namespace glimmer {

struct WatchRange {
    double lo = 0, hi = 1;
};

struct WatchStats {
    int width = 0, height = 0;
    int components = 0;  // 1 to 4 (the most seen); 0 when the line ran nowhere
    int kind = 0;        // WatchKind (shader/watch_rewrite.h): float, int, uint, bool
    std::array<double, 4> lo{}, hi{};  // per component, over the finite values
    WatchRange range;    // the range shown: the fixed one, else the values' own (all components)
    bool fixed = false;
    long long drawn = 0;     // pixels a fragment of the watched draws ran at
    long long reached = 0;   // of those, where the watched line ran
    long long nan = 0, inf = 0, below = 0, above = 0;  // pixels (any component); NaN counts before Inf before range
};

// The statistics of a capture; `fixed` sets the range instead of the values.
WatchStats watchStats(const Image& value, const Image& info, std::optional<WatchRange> fixed = std::nullopt);

// 1 / (hi - lo) in float, the picture's scale; 0 when that is not a
// finite number above 0 (a range of one value, shown as mid grey).
inline float watchScale(float lo, float hi) {
    const float span = hi - lo, scale = 1.f / span;
    return span > 0 && scale < std::numeric_limits<float>::infinity() ? scale : 0.f;
}

// The range shown: the fixed one, else the finite values' own over every
// component (s.lo, s.hi, s.components), else 0..1 when there are none.
WatchRange watchRangeOf(const WatchStats& s, std::optional<WatchRange> fixed);

// The picture described at the top, RGBA8, row 0 at the top.
Image watchPicture(const Image& value, const Image& info, const WatchStats& stats);

// The marker colours, for the legend and the tests.
enum class WatchMark { None, NaN, Inf, Below, Above, NotReached, NotDrawn };
struct WatchMarker {
    WatchMark mark;
    unsigned char r, g, b;
    const char* name;
};
extern const WatchMarker kWatchMarkers[6];
// What the picture shows at a pixel: a value, or which marker.
WatchMark watchMarkAt(const Image& value, const Image& info, const WatchStats& stats, int x, int y);

// "vec3", "int", "bvec2", ... for a component count and kind.
std::string watchTypeName(int components, int kind);

// One line: the type, the range shown, and every count that is not zero:
// "vec3 over 512x512: range 0 .. 0.9922 (its own); x 0 .. 0.99, y ..., 37 pixels NaN".
std::string watchSummary(const WatchStats& stats);

// The exact value at pixel x, y (row 0 at the top), every component with
// the digits a float needs: "vec3(0.25, 0.5, 1)"; or why there is none.
std::string watchValueAt(const Image& value, const Image& info, int x, int y);

}  // namespace glimmer
