#include "reports/plot_labels.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace candela::reports {

namespace {

constexpr int kGap = 3;      // between a marker and a label next to it
constexpr int kReach = 120;  // how far from its point a label may go, in pixels
constexpr int kStep = 2;     // of the search grid
constexpr int kLabelGap = 3; // between two labels, so that neighbours do not read as one

// Distance from the pixel (x, y) to the nearest pixel of `b`.
double distance(int x, int y, const PixelBox& b) {
    const int dx = std::max({b.x0 - x, 0, x - (b.x1 - 1)});
    const int dy = std::max({b.y0 - y, 0, y - (b.y1 - 1)});
    return std::hypot(double(dx), double(dy));
}

// The positions right next to the marker, in order of preference: right, left, above and below
// (each to the right, then to the left, then centred).
std::vector<PixelBox> adjacentPositions(const LabelRequest& r) {
    const int c = r.clearance + kGap, w = r.width, h = r.height;
    const int midY = r.y - h / 2, midX = r.x - w / 2;
    const int aboveY = r.y - c - h + 1, belowY = r.y + c;
    return {{r.x + c, midY, r.x + c + w, midY + h},
            {r.x - c - w + 1, midY, r.x - c + 1, midY + h},
            {r.x, aboveY, r.x + w, aboveY + h},
            {r.x, belowY, r.x + w, belowY + h},
            {r.x - w + 1, aboveY, r.x + 1, aboveY + h},
            {r.x - w + 1, belowY, r.x + 1, belowY + h},
            {midX, aboveY, midX + w, aboveY + h},
            {midX, belowY, midX + w, belowY + h}};
}

}  // namespace

std::vector<LabelPlacement> placeLabels(const std::vector<LabelRequest>& labels, const std::vector<PixelBox>& obstacles,
                                        const PixelBox& area) {
    std::vector<LabelPlacement> out(labels.size());
    std::vector<PixelBox> taken;
    auto isFree = [&](const PixelBox& box) {
        if (!area.contains(box)) return false;
        for (const PixelBox& o : obstacles)
            if (box.intersects(o)) return false;
        for (const PixelBox& t : taken)
            if (box.intersects({t.x0 - kLabelGap, t.y0 - kLabelGap, t.x1 + kLabelGap, t.y1 + kLabelGap})) return false;
        return true;
    };
    for (size_t i = 0; i < labels.size(); ++i) {
        const LabelRequest& r = labels[i];
        if (r.width <= 0 || r.height <= 0) continue;
        const std::vector<PixelBox> adjacent = adjacentPositions(r);
        LabelPlacement& placed = out[i];
        placed.box = adjacent.front();
        placed.free = false;
        for (const PixelBox& box : adjacent)
            if (isFree(box)) {
                placed = {box, false, true};
                break;
            }
        if (!placed.free) {
            // Every free box within reach, the nearest kept; at equal distance the one nearer the
            // point's height, then the one to its right.
            double best = INFINITY;
            for (int dy = -kReach; dy <= kReach; dy += kStep)
                for (int dx = -kReach - r.width; dx <= kReach; dx += kStep) {
                    const PixelBox box{r.x + dx, r.y + dy, r.x + dx + r.width, r.y + dy + r.height};
                    const double d = distance(r.x, r.y, box);
                    if (d > kReach) continue;
                    const double score = d + 0.05 * std::abs((box.y0 + box.y1) / 2 - r.y) + (box.x1 <= r.x ? 0.5 : 0.0);
                    if (score >= best || !isFree(box)) continue;
                    best = score;
                    placed = {box, d > r.clearance + kGap + 2, true};
                }
        }
        taken.push_back(placed.box);
    }
    return out;
}

}  // namespace candela::reports
