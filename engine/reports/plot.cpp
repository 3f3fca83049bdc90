#include "reports/plot.h"

#include "assets/image_file.h"
#include "core/errors.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace candela::reports {

namespace {

using Rgb = std::array<uint8_t, 3>;

constexpr Rgb kSeriesColors[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},
                                 {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127}};

bool usable(const PlotPoint& p) { return std::isfinite(p.x) && std::isfinite(p.y) && p.x > 0 && p.y > 0; }

double lowOf(double value, double low) { return std::isnan(low) ? value : low; }
double highOf(double value, double high) { return std::isnan(high) ? value : high; }

constexpr int kMarkerHalf = 4;  // markers are 9×9 pixels
constexpr int kRingRadius = 11;
constexpr int kLabelPad = 1;    // around a label's ink, in its box

class Canvas {
public:
    Canvas(uint32_t width, uint32_t height) : mWidth(width), mHeight(height), mPixels(size_t(width) * height * 4, 255) {}

    void pixel(int x, int y, Rgb c) {
        if (x < 0 || y < 0 || x >= int(mWidth) || y >= int(mHeight)) return;
        uint8_t* p = &mPixels[(size_t(y) * mWidth + x) * 4];
        p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
    }
    void rect(int x0, int y0, int x1, int y1, Rgb c) {
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) pixel(x, y, c);
    }
    void line(double x0, double y0, double x1, double y1, Rgb c, int thickness = 1) {
        const int steps = int(std::max(std::abs(x1 - x0), std::abs(y1 - y0))) + 1;
        for (int i = 0; i <= steps; ++i) {
            const double t = double(i) / steps;
            const int x = int(std::lround(x0 + (x1 - x0) * t)), y = int(std::lround(y0 + (y1 - y0) * t));
            rect(x - thickness / 2, y - thickness / 2, x - thickness / 2 + thickness, y - thickness / 2 + thickness, c);
        }
    }
    void ring(double cx, double cy, double radius, Rgb c) {
        for (int i = 0; i < 360; ++i) {
            const double a = i * 3.14159265358979 / 180.0;
            rect(int(cx + radius * std::cos(a)) - 1, int(cy + radius * std::sin(a)) - 1,
                 int(cx + radius * std::cos(a)) + 1, int(cy + radius * std::sin(a)) + 1, c);
        }
    }
    // stb_easy_font text at (x, y) (top left), scaled by `scale`.
    void text(int x, int y, const std::string& s, Rgb c, int scale = 1) {
        static std::array<char, 60000> buffer;
        std::string copy = s;
        const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
        const auto* v = reinterpret_cast<const float*>(buffer.data());  // 4 vertices × (x, y, z, colour) per quad
        for (int q = 0; q < quads; ++q) {
            const float* quad = v + q * 16;
            rect(x + int(quad[0]) * scale, y + int(quad[1]) * scale, x + int(quad[8]) * scale, y + int(quad[9]) * scale, c);
        }
    }
    static int textWidth(const std::string& s, int scale = 1) {
        std::string copy = s;
        return stb_easy_font_width(copy.data()) * scale;
    }
    // The pixels text(0, 0, s) covers (empty for text that draws nothing).
    static PixelBox inkBox(const std::string& s) {
        static std::array<char, 60000> buffer;
        std::string copy = s;
        const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
        const auto* v = reinterpret_cast<const float*>(buffer.data());
        PixelBox box{INT32_MAX, INT32_MAX, INT32_MIN, INT32_MIN};
        for (int q = 0; q < quads; ++q) {
            const float* quad = v + q * 16;
            box.x0 = std::min(box.x0, int(quad[0])), box.y0 = std::min(box.y0, int(quad[1]));
            box.x1 = std::max(box.x1, int(quad[8])), box.y1 = std::max(box.y1, int(quad[9]));
        }
        return quads > 0 ? box : PixelBox{};
    }
    const std::vector<uint8_t>& pixels() const { return mPixels; }

private:
    uint32_t mWidth, mHeight;
    std::vector<uint8_t> mPixels;
};

std::string decadeLabel(int exponent) {
    if (exponent >= 0 && exponent <= 4) return std::to_string(int(std::lround(std::pow(10.0, exponent))));
    if (exponent < 0 && exponent >= -3) {
        std::string s = "0.";
        for (int i = 1; i < -exponent; ++i) s += "0";
        return s + "1";
    }
    return "1e" + std::to_string(exponent);
}

// Room right of the plot for the legend: its longest name after the swatch, at least 200 pixels.
int legendWidth(const PlotSpec& spec) {
    int widest = Canvas::textWidth("default setting");
    for (const std::string& name : spec.series) widest = std::max(widest, Canvas::textWidth(name));
    return std::clamp(widest + 44, 200, int(spec.width) / 2);
}

// The plot area and the log-log mapping of a spec's points to pixels.
struct Layout {
    int left = 90, right = 0, top = 50, bottom = 0;
    double lx0 = 0, lx1 = 1, ly0 = 0, ly1 = 1;  // decades at the axes' ends

    explicit Layout(const PlotSpec& spec) : right(int(spec.width) - legendWidth(spec)), bottom(int(spec.height) - 60) {
        double minX = INFINITY, maxX = -INFINITY, minY = INFINITY, maxY = -INFINITY;
        for (const PlotPoint& p : spec.points) {
            if (!usable(p)) continue;
            // A spread reaching 0 has no place on a log axis: its bar stops at the value.
            minX = std::min(minX, p.xLow > 0 ? p.xLow : p.x), maxX = std::max(maxX, highOf(p.x, p.xHigh));
            minY = std::min(minY, p.yLow > 0 ? p.yLow : p.y), maxY = std::max(maxY, highOf(p.y, p.yHigh));
        }
        if (!std::isfinite(minX) || !std::isfinite(maxX)) minX = 1, maxX = 10, minY = 1, maxY = 10;
        lx0 = std::floor(std::log10(minX)), lx1 = std::max(std::ceil(std::log10(maxX)), lx0 + 1);
        ly0 = std::floor(std::log10(minY)), ly1 = std::max(std::ceil(std::log10(maxY)), ly0 + 1);
    }
    double sx(double x) const { return left + (std::log10(x) - lx0) / (lx1 - lx0) * (right - left); }
    double sy(double y) const { return bottom - (std::log10(y) - ly0) / (ly1 - ly0) * (bottom - top); }
    // Where labels may go: inside the axes.
    PixelBox labelArea() const { return {left + 3, top, right, bottom - 2}; }
};

PixelBox markerBox(const Layout& layout, const PlotSpec& spec, size_t i) {
    const PlotPoint& p = spec.points[i];
    if (!usable(p)) return {};
    const int x = int(layout.sx(p.x)), y = int(layout.sy(p.y));
    const int half = spec.highlight == i ? kRingRadius + 1 : kMarkerHalf;
    return {x - half, y - half, x + half + 1, y + half + 1};
}

// The pixels of a point's spread bars, ticks included (none without a spread).
std::vector<PixelBox> barBoxes(const Layout& layout, const PlotPoint& p) {
    std::vector<PixelBox> out;
    if (!usable(p)) return out;
    const int x = int(layout.sx(p.x)), y = int(layout.sy(p.y));
    if (!std::isnan(p.xLow) && !std::isnan(p.xHigh) && p.xLow > 0)
        out.push_back({int(layout.sx(p.xLow)) - 1, y - 3, int(layout.sx(p.xHigh)) + 2, y + 4});
    if (!std::isnan(p.yLow) && !std::isnan(p.yHigh) && p.yLow > 0)
        out.push_back({x - 3, int(layout.sy(p.yHigh)) - 1, x + 4, int(layout.sy(p.yLow)) + 2});
    return out;
}

std::vector<LabelPlacement> placeLabels(const Layout& layout, const PlotSpec& spec) {
    // The ringed point first: it is the one a reader looks for.
    std::vector<size_t> order;
    if (spec.highlight && *spec.highlight < spec.points.size()) order.push_back(*spec.highlight);
    for (size_t i = 0; i < spec.points.size(); ++i)
        if (!spec.highlight || i != *spec.highlight) order.push_back(i);
    std::vector<PixelBox> markers;
    std::vector<LabelRequest> requests;
    for (size_t i : order) {
        const PixelBox marker = markerBox(layout, spec, i);
        if (!marker.empty()) markers.push_back(marker);
        for (const PixelBox& bar : barBoxes(layout, spec.points[i])) markers.push_back(bar);
        LabelRequest r{.x = (marker.x0 + marker.x1) / 2, .y = (marker.y0 + marker.y1) / 2, .clearance = (marker.x1 - marker.x0) / 2};
        const PixelBox ink = Canvas::inkBox(spec.points[i].label);
        if (!marker.empty() && !ink.empty())
            r.width = ink.x1 - ink.x0 + 2 * kLabelPad, r.height = ink.y1 - ink.y0 + 2 * kLabelPad;
        requests.push_back(r);
    }
    // The Pareto front's line, as small boxes along it: a label over it would be crossed out.
    const std::vector<size_t> front = spec.paretoLine ? paretoFront(spec.points) : std::vector<size_t>{};
    for (size_t k = 1; k < front.size(); ++k) {
        const double x0 = layout.sx(spec.points[front[k - 1]].x), y0 = layout.sy(spec.points[front[k - 1]].y);
        const double x1 = layout.sx(spec.points[front[k]].x), y1 = layout.sy(spec.points[front[k]].y);
        const int steps = int(std::max(std::abs(x1 - x0), std::abs(y1 - y0)) / 2) + 1;
        for (int i = 0; i <= steps; ++i) {
            const int x = int(std::lround(x0 + (x1 - x0) * i / steps)), y = int(std::lround(y0 + (y1 - y0) * i / steps));
            markers.push_back({x - 1, y - 1, x + 2, y + 2});
        }
    }
    const std::vector<LabelPlacement> placed = reports::placeLabels(requests, markers, layout.labelArea());
    std::vector<LabelPlacement> out(spec.points.size());
    for (size_t k = 0; k < order.size(); ++k) out[order[k]] = placed[k];
    return out;
}

}  // namespace

bool dominates(const PlotPoint& a, const PlotPoint& b) {
    const bool clearlyWorseX = lowOf(a.x, a.xLow) > highOf(b.x, b.xHigh), clearlyWorseY = lowOf(a.y, a.yLow) > highOf(b.y, b.yHigh);
    const bool clearlyBetterX = highOf(a.x, a.xHigh) < lowOf(b.x, b.xLow), clearlyBetterY = highOf(a.y, a.yHigh) < lowOf(b.y, b.yLow);
    return !clearlyWorseX && !clearlyWorseY && (clearlyBetterX || clearlyBetterY);
}

std::vector<LabelPlacement> placePlotLabels(const PlotSpec& spec) { return placeLabels(Layout(spec), spec); }

PixelBox plotMarkerBox(const PlotSpec& spec, size_t i) {
    return i < spec.points.size() ? markerBox(Layout(spec), spec, i) : PixelBox{};
}

std::vector<size_t> paretoFront(const std::vector<PlotPoint>& points) {
    std::vector<size_t> order;
    for (size_t i = 0; i < points.size(); ++i)
        if (usable(points[i])) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return points[a].x < points[b].x || (points[a].x == points[b].x && points[a].y < points[b].y);
    });
    std::vector<size_t> front;
    for (size_t i : order)
        if (std::none_of(order.begin(), order.end(), [&](size_t j) { return j != i && dominates(points[j], points[i]); }))
            front.push_back(i);
    return front;
}

void writeLogLogPlot(const std::filesystem::path& path, const PlotSpec& spec) {
    Canvas canvas(spec.width, spec.height);
    const Layout layout(spec);
    const int left = layout.left, right = layout.right, top = layout.top, bottom = layout.bottom;
    const double lx0 = layout.lx0, lx1 = layout.lx1, ly0 = layout.ly0, ly1 = layout.ly1;
    auto sx = [&](double x) { return layout.sx(x); };
    auto sy = [&](double y) { return layout.sy(y); };

    const Rgb grid{225, 225, 225}, axis{60, 60, 60}, ink{20, 20, 20};
    for (int e = int(lx0); e <= int(lx1); ++e) {
        for (int k = 1; k < 10 && e + std::log10(k) <= lx1; ++k)
            canvas.line(sx(k * std::pow(10.0, e)), top, sx(k * std::pow(10.0, e)), bottom, k == 1 ? Rgb{200, 200, 200} : grid);
        const std::string label = decadeLabel(e);
        canvas.text(int(sx(std::pow(10.0, e))) - Canvas::textWidth(label) / 2, bottom + 8, label, ink);
    }
    for (int e = int(ly0); e <= int(ly1); ++e) {
        for (int k = 1; k < 10 && e + std::log10(k) <= ly1; ++k)
            canvas.line(left, sy(k * std::pow(10.0, e)), right, sy(k * std::pow(10.0, e)), k == 1 ? Rgb{200, 200, 200} : grid);
        const std::string label = decadeLabel(e);
        canvas.text(left - 8 - Canvas::textWidth(label), int(sy(std::pow(10.0, e))) - 4, label, ink);
    }
    canvas.line(left, bottom, right, bottom, axis, 2);
    canvas.line(left, top, left, bottom, axis, 2);
    canvas.text(left, 15, spec.title, ink, 2);
    canvas.text((left + right) / 2 - Canvas::textWidth(spec.xLabel) / 2, bottom + 30, spec.xLabel, ink);
    canvas.text(10, top - 20, spec.yLabel, ink);

    const std::vector<size_t> front = spec.paretoLine ? paretoFront(spec.points) : std::vector<size_t>{};
    for (size_t i = 1; i < front.size(); ++i)
        canvas.line(sx(spec.points[front[i - 1]].x), sy(spec.points[front[i - 1]].y), sx(spec.points[front[i]].x),
                    sy(spec.points[front[i]].y), Rgb{0, 0, 0}, 2);
    // Spreads as bars with end ticks, under the markers.
    for (const PlotPoint& p : spec.points) {
        if (!usable(p)) continue;
        const Rgb c = kSeriesColors[p.series % std::size(kSeriesColors)];
        const double x = sx(p.x), y = sy(p.y);
        if (!std::isnan(p.xLow) && !std::isnan(p.xHigh) && p.xLow > 0) {
            canvas.line(sx(p.xLow), y, sx(p.xHigh), y, c);
            for (const double end : {sx(p.xLow), sx(p.xHigh)}) canvas.line(end, y - 3, end, y + 3, c);
        }
        if (!std::isnan(p.yLow) && !std::isnan(p.yHigh) && p.yLow > 0) {
            canvas.line(x, sy(p.yLow), x, sy(p.yHigh), c);
            for (const double end : {sy(p.yLow), sy(p.yHigh)}) canvas.line(x - 3, end, x + 3, end, c);
        }
    }
    // Leader lines, then markers, then the labels over everything.
    const std::vector<LabelPlacement> labels = placeLabels(layout, spec);
    for (int layer = 0; layer < 3; ++layer)
        for (size_t i = 0; i < spec.points.size(); ++i) {
            const PlotPoint& p = spec.points[i];
            if (!usable(p)) continue;
            const Rgb c = kSeriesColors[p.series % std::size(kSeriesColors)];
            const int x = int(sx(p.x)), y = int(sy(p.y));
            const PixelBox& box = labels[i].box;
            if (layer == 0 && labels[i].leader) {
                const Rgb faint{uint8_t((c[0] + 255) / 2), uint8_t((c[1] + 255) / 2), uint8_t((c[2] + 255) / 2)};
                canvas.line(x, y, std::clamp(x, box.x0, box.x1 - 1), std::clamp(y, box.y0, box.y1 - 1), faint);
            } else if (layer == 1) {
                canvas.rect(x - kMarkerHalf, y - kMarkerHalf, x + kMarkerHalf + 1, y + kMarkerHalf + 1, c);
            } else if (layer == 2 && !box.empty()) {
                const PixelBox glyphs = Canvas::inkBox(p.label);
                canvas.text(box.x0 + kLabelPad - glyphs.x0, box.y0 + kLabelPad - glyphs.y0, p.label, c);
            }
        }
    if (spec.highlight && *spec.highlight < spec.points.size() && usable(spec.points[*spec.highlight]))
        canvas.ring(sx(spec.points[*spec.highlight].x), sy(spec.points[*spec.highlight].y), kRingRadius, Rgb{220, 0, 0});

    int ly = top;
    for (size_t s = 0; s < spec.series.size(); ++s, ly += 18) {
        canvas.rect(right + 20, ly, right + 29, ly + 9, kSeriesColors[s % std::size(kSeriesColors)]);
        canvas.text(right + 36, ly, spec.series[s], ink);
    }
    if (spec.paretoLine) {
        canvas.line(right + 16, ly + 5, right + 32, ly + 5, Rgb{0, 0, 0}, 2);
        canvas.text(right + 36, ly, "Pareto front", ink);
    } else {
        ly -= 18;
    }
    if (spec.highlight) {
        ly += 18;
        canvas.ring(right + 24, ly + 4, 6, Rgb{220, 0, 0});
        canvas.text(right + 36, ly, "default setting", ink);
    }
    assets::writePng(path, spec.width, spec.height, canvas.pixels());
}

}  // namespace candela::reports
