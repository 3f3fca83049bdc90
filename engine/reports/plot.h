#pragma once
// Log-log scatter plots for reports (`candela ibl-report`, `quality-report`): points in series with
// the spread of their measurements as bars, the Pareto front (the points no other point dominates
// beyond the spread: dominates()) drawn as a line, one point ringed (the default setting),
// decade grid lines, and labels placed where they overlap nothing (plot_labels.h). Written as PNG.
// Text is stb_easy_font's bitmap font.

#include "reports/plot_labels.h"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace candela::reports {

struct PlotPoint {
    double x = 0;  // > 0 (log axis); points with x ≤ 0 or y ≤ 0 are not drawn
    double y = 0;
    std::string label;    // drawn next to the point (may be empty)
    uint32_t series = 0;  // index into PlotSpec::series (colour and legend)
    // The spread of repeated measurements of x and y (e.g. the lowest and highest of the repeats),
    // drawn as bars; NaN: none (the value is exact). Precondition: low ≤ value ≤ high.
    double xLow = NAN, xHigh = NAN;
    double yLow = NAN, yHigh = NAN;
};

struct PlotSpec {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    std::vector<std::string> series;  // legend names
    std::vector<PlotPoint> points;
    std::optional<size_t> highlight;  // index of a point to ring and name in the legend ("default")
    bool paretoLine = true;           // draw the Pareto front (reports of cost against error)
    uint32_t width = 960;
    uint32_t height = 640;
};

// Whether `a` dominates `b` when minimising both x and y, with the spread of the measurements:
// `a` is better by more than the spreads on at least one axis (its high end below `b`'s low end)
// and not worse by more than them on the other (a value without a spread is its own low and high
// end). Two points whose spreads overlap on both axes dominate neither, and a point survives
// against one with a lower y only by being cheaper beyond the spread: noise neither removes a
// point from the front nor puts one on it.
bool dominates(const PlotPoint& a, const PlotPoint& b);

// Indices of the points no other point dominates, in increasing x (equal points all stay). Points
// with non-finite or non-positive coordinates are ignored.
std::vector<size_t> paretoFront(const std::vector<PlotPoint>& points);

// Where writeLogLogPlot draws each point's label (plot_labels.h), in the order of spec.points: the
// ringed point's label first, then the others in order. Empty boxes for points without a label
// or not drawn.
std::vector<LabelPlacement> placePlotLabels(const PlotSpec& spec);
// The pixel box of the marker writeLogLogPlot draws for spec.points[i] (empty when not drawn).
PixelBox plotMarkerBox(const PlotSpec& spec, size_t i);

// Draws the plot and writes it as PNG. Throws UserError naming the file if it cannot be written.
void writeLogLogPlot(const std::filesystem::path& path, const PlotSpec& spec);

}  // namespace candela::reports
