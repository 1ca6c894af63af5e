#include "bloom/label_placement.h"

#include <algorithm>
#include <cmath>

namespace glimmer {
namespace {

bool inside(const PixelBox& b, const PixelBox& bounds) {
    return b.x >= bounds.x && b.y >= bounds.y && b.x + b.w <= bounds.x + bounds.w && b.y + b.h <= bounds.y + bounds.h;
}

// The boxes next to the dot, best first: to the right reads most naturally
// on a chart whose x axis is time.
std::vector<PixelBox> nearCandidates(const LabelRequest& l, int gap) {
    const int w = l.w, h = l.h, x = l.x, y = l.y;
    return {{x + gap, y - h / 2, w, h},         {x - gap - w, y - h / 2, w, h}, {x - w / 2, y - gap - h, w, h},
            {x - w / 2, y + gap, w, h},         {x + gap, y - gap - h, w, h},   {x - gap - w, y - gap - h, w, h},
            {x + gap, y + gap, w, h},           {x - gap - w, y + gap, w, h}};
}

}  // namespace

bool boxesOverlap(const PixelBox& a, const PixelBox& b, int margin) {
    return a.x < b.x + b.w + margin && b.x < a.x + a.w + margin && a.y < b.y + b.h + margin &&
           b.y < a.y + a.h + margin;
}

std::vector<PlacedLabel> placeLabels(const std::vector<LabelRequest>& labels, const PixelBox& bounds, int dotRadius,
                                     const std::vector<PixelBox>& obstacles, int margin) {
    // Every dot is an obstacle for every label, its own included.
    std::vector<PixelBox> blocked = obstacles;
    for (const auto& l : labels)
        blocked.push_back({l.x - dotRadius, l.y - dotRadius, 2 * dotRadius + 1, 2 * dotRadius + 1});
    auto isFree = [&](const PixelBox& b) {
        if (!inside(b, bounds)) return false;
        for (const auto& o : blocked)
            if (boxesOverlap(b, o, margin)) return false;
        return true;
    };

    std::vector<PlacedLabel> out;
    const int gap = dotRadius + margin + 1;
    for (const auto& l : labels) {
        PlacedLabel p;
        bool found = false;
        for (const PixelBox& b : nearCandidates(l, gap))
            if (isFree(b)) {
                p.box = b, found = true;
                break;
            }
        // Rings further out, 24 directions each, nearest first: the label
        // stays as close to its dot as the crowd allows.
        const int far = std::max(bounds.w, bounds.h);
        for (int d = gap + std::max(l.w, l.h) / 2 + 6; !found && d <= far; d += 6)
            for (int k = 0; k < 24 && !found; ++k) {
                const double a = k * 2 * M_PI / 24;
                const int cx = l.x + int(std::lround(d * std::cos(a))), cy = l.y + int(std::lround(d * std::sin(a)));
                const PixelBox b{cx - l.w / 2, cy - l.h / 2, l.w, l.h};
                if (isFree(b)) p.box = b, p.leader = true, found = true;
            }
        if (!found) {
            // Nowhere free (more text than chart): to the right of the dot,
            // kept inside the bounds, and said so.
            PixelBox b = nearCandidates(l, gap).front();
            b.x = std::clamp(b.x, bounds.x, std::max(bounds.x, bounds.x + bounds.w - b.w));
            b.y = std::clamp(b.y, bounds.y, std::max(bounds.y, bounds.y + bounds.h - b.h));
            p.box = b, p.free = false;
        }
        blocked.push_back(p.box);
        out.push_back(p);
    }
    return out;
}

}  // namespace glimmer
