#pragma once
// Placement of the labels of a plot's points so that they overlap neither each other nor any
// point's marker: each label in turn takes the nearest free position around its point (right of
// it first, as plots usually put labels), and a label pushed away from its point gets a leader
// line. Pure geometry in pixels; plot.cpp maps the points and measures the text.

#include <cstdint>
#include <vector>

namespace candela::reports {

// A rectangle in pixels, [x0, x1) × [y0, y1) (y down). Empty when x1 ≤ x0 or y1 ≤ y0.
struct PixelBox {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    // Whether the two boxes share a pixel (empty boxes share none).
    bool intersects(const PixelBox& o) const {
        return !empty() && !o.empty() && x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
    bool contains(const PixelBox& o) const { return o.x0 >= x0 && o.x1 <= x1 && o.y0 >= y0 && o.y1 <= y1; }
};

// One label to place: the centre of its point's marker, the marker's half size (the label keeps
// clear of it), and the size of the text's box. width 0: no label.
struct LabelRequest {
    int x = 0, y = 0;
    int clearance = 5;
    int width = 0, height = 0;
};

struct LabelPlacement {
    PixelBox box;         // empty for a request without a label
    bool leader = false;  // placed away from its point: draw a line from the point to the box
    bool free = true;     // false: no free position within reach, the box overlaps something
};

// Places the labels in the order given (earlier ones get the better positions). Each box lies
// inside `area` when it fits there, meets no `obstacles` box (the markers) and keeps a few pixels
// from every box placed before it; when nothing within reach is free, the label takes its first position with
// LabelPlacement::free false. Returns one placement per request, in the same order.
std::vector<LabelPlacement> placeLabels(const std::vector<LabelRequest>& labels, const std::vector<PixelBox>& obstacles,
                                        const PixelBox& area);

}  // namespace candela::reports
