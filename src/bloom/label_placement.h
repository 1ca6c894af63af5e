// Where a chart's labels go so that none covers another label or a dot: a
// pure function of pixel positions and sizes, so tests can check it without
// drawing. Used by the Pareto chart (bloom/pareto_chart.h).
#pragma once
#include <vector>

namespace glimmer {

// A rectangle in pixels: top-left corner, width, height.
struct PixelBox {
    int x = 0, y = 0, w = 0, h = 0;
};
// True when the two share a pixel, or come within `margin` pixels of it.
bool boxesOverlap(const PixelBox& a, const PixelBox& b, int margin = 0);

// One label: the centre of its dot and the size of its text.
struct LabelRequest {
    int x = 0, y = 0;
    int w = 0, h = 0;
};

struct PlacedLabel {
    PixelBox box;
    bool leader = false;  // placed away from its dot: draw a line to it
    bool free = true;     // false: no free place was found; box overlaps something
};

// Places the labels in order. For each, the places next to its dot are tried
// first (right, left, above, below and the corners); where all of those
// cover a dot, an obstacle or a label already placed, places on rings further
// out are tried, and the label gets a leader line. Every box stays inside
// `bounds`; boxes keep `margin` pixels from each other and from the dots
// (squares of `dotRadius` around each request's x, y) and `obstacles`.
std::vector<PlacedLabel> placeLabels(const std::vector<LabelRequest>& labels, const PixelBox& bounds, int dotRadius,
                                     const std::vector<PixelBox>& obstacles = {}, int margin = 2);

}  // namespace glimmer
