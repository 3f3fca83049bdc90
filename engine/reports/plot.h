#pragma once
// Log-log scatter plots for reports (`candela ibl-report`): points in series, the Pareto front
// (the points no other point beats on both axes) drawn as a line, one point ringed (the default
// setting), decade grid lines and labels. Written as PNG. Text is stb_easy_font's bitmap font.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace candela::io {

struct PlotPoint {
    double x = 0;  // > 0 (log axis); points with x ≤ 0 or y ≤ 0 are not drawn
    double y = 0;
    std::string label;    // drawn next to the point (may be empty)
    uint32_t series = 0;  // index into PlotSpec::series (colour and legend)
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

// Indices of the Pareto-optimal points for minimising both x and y (ties: the first kept), in
// increasing x. Points with non-finite or non-positive coordinates are ignored.
std::vector<size_t> paretoFront(const std::vector<PlotPoint>& points);

// Draws the plot and writes it as PNG. Throws UserError naming the file if it cannot be written.
void writeLogLogPlot(const std::filesystem::path& path, const PlotSpec& spec);

}  // namespace candela::io
