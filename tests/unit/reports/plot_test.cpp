// Report plots: the Pareto front with the spread of measurements, label placement, the PNG writer.

#include "reports/plot.h"

#include "temp_dir.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>

namespace candela::reports {
namespace {

TEST(Plot, ParetoFrontKeepsThePointsNoOtherBeatsOnBothAxes) {
    const std::vector<PlotPoint> points{
        {.x = 1, .y = 10}, {.x = 2, .y = 5}, {.x = 3, .y = 6},  // (3, 6) is beaten by (2, 5)
        {.x = 4, .y = 1}, {.x = 4, .y = 2},                      // equal x: the lower y only
        {.x = 8, .y = 1},                                        // equal y, slower: beaten
        {.x = -1, .y = 0.1}, {.x = NAN, .y = 0.01}, {.x = 5, .y = 0},  // not drawable on log axes
    };
    EXPECT_EQ(paretoFront(points), (std::vector<size_t>{0, 1, 3}));
    EXPECT_TRUE(paretoFront({}).empty());
}

TEST(Plot, OnlyADifferenceBeyondTheSpreadDominates) {
    // Same error, times overlapping: neither dominates, both stay on the front.
    const PlotPoint fast{.x = 1.0, .y = 0.5, .xLow = 0.9, .xHigh = 1.2};
    const PlotPoint slow{.x = 1.1, .y = 0.5, .xLow = 1.0, .xHigh = 1.3};
    EXPECT_FALSE(dominates(fast, slow));
    EXPECT_FALSE(dominates(slow, fast));
    EXPECT_EQ(paretoFront({fast, slow}), (std::vector<size_t>{0, 1}));
    // Same error, the spreads apart: the faster one dominates.
    const PlotPoint clearlySlower{.x = 1.4, .y = 0.5, .xLow = 1.3, .xHigh = 1.5};
    EXPECT_TRUE(dominates(fast, clearlySlower));
    EXPECT_EQ(paretoFront({fast, clearlySlower}), (std::vector<size_t>{0}));
    // A lower error (beyond its zero spread) at a time within the spread dominates, even where
    // noise put the other's median lower: a faster median alone does not keep a point optimal.
    const PlotPoint better{.x = 1.05, .y = 0.4, .xLow = 0.95, .xHigh = 1.25};
    EXPECT_TRUE(dominates(better, slow));
    EXPECT_TRUE(dominates(better, fast));
    EXPECT_EQ(paretoFront({fast, slow, better}), (std::vector<size_t>{2}));
    // The ibl-report's case: sh9:8 no faster than sh9:16 beyond the spread, and less accurate.
    const PlotPoint sh8{.x = 4.27, .y = 0.09, .xLow = 3.9, .xHigh = 5.6};
    const PlotPoint sh16{.x = 5.42, .y = 0.05, .xLow = 4.1, .xHigh = 6.0};
    EXPECT_TRUE(dominates(sh16, sh8));
    EXPECT_FALSE(dominates(sh8, sh16));
    // Faster beyond the spread keeps a less accurate point on the front.
    const PlotPoint cheap{.x = 0.5, .y = 0.6, .xLow = 0.45, .xHigh = 0.55};
    EXPECT_FALSE(dominates(better, cheap));
    EXPECT_FALSE(dominates(cheap, better));
    EXPECT_EQ(paretoFront({better, cheap}), (std::vector<size_t>{1, 0}));
    // Overlapping on both axes: nothing dominates.
    const PlotPoint noisy{.x = 1.0, .y = 0.45, .xLow = 0.9, .xHigh = 1.2, .yLow = 0.38, .yHigh = 0.52};
    EXPECT_FALSE(dominates(noisy, slow));
    EXPECT_FALSE(dominates(slow, noisy));
    // Equal points both stay.
    EXPECT_EQ(paretoFront({fast, fast}), (std::vector<size_t>{0, 1}));
}

TEST(Plot, LabelsGoRightOfTheirPointWhenFree) {
    const std::vector<LabelPlacement> placed = placeLabels({{.x = 100, .y = 100, .clearance = 4, .width = 30, .height = 9}}, {},
                                                           {0, 0, 400, 400});
    ASSERT_EQ(placed.size(), 1u);
    EXPECT_TRUE(placed[0].free);
    EXPECT_FALSE(placed[0].leader);
    EXPECT_GT(placed[0].box.x0, 104);
    EXPECT_LT(placed[0].box.x0, 112);
    EXPECT_LE(placed[0].box.y0, 100);
    EXPECT_GE(placed[0].box.y1, 100);
}

TEST(Plot, LabelsWithNoRoomAreMarkedNotFree) {
    // A box filled by an obstacle but for the point: nowhere to go.
    const std::vector<LabelPlacement> placed =
        placeLabels({{.x = 50, .y = 50, .clearance = 4, .width = 30, .height = 9}}, {{0, 0, 45, 100}, {56, 0, 100, 100},
                                                                                    {45, 0, 56, 45}, {45, 56, 56, 100}},
                    {0, 0, 100, 100});
    EXPECT_FALSE(placed[0].free);
    EXPECT_FALSE(placed[0].box.empty());
}

// Every label box of a crowded plot: inside the image, clear of every marker and of each other.
void expectReadable(const PlotSpec& spec) {
    const std::vector<LabelPlacement> labels = placePlotLabels(spec);
    ASSERT_EQ(labels.size(), spec.points.size());
    const PixelBox image{0, 0, int(spec.width), int(spec.height)};
    for (size_t i = 0; i < labels.size(); ++i) {
        if (spec.points[i].label.empty()) {
            EXPECT_TRUE(labels[i].box.empty());
            continue;
        }
        EXPECT_TRUE(labels[i].free) << spec.points[i].label;
        EXPECT_FALSE(labels[i].box.empty()) << spec.points[i].label;
        EXPECT_TRUE(image.contains(labels[i].box)) << spec.points[i].label;
        for (size_t j = 0; j < spec.points.size(); ++j) {
            EXPECT_FALSE(labels[i].box.intersects(plotMarkerBox(spec, j)))
                << "label '" << spec.points[i].label << "' covers the marker of point " << j;
            if (j > i) {
                const PixelBox& b = labels[j].box;  // with a pixel between them: neighbours do not read as one
                EXPECT_FALSE(labels[i].box.intersects({b.x0 - 1, b.y0 - 1, b.x1 + 1, b.y1 + 1}))
                    << "labels '" << spec.points[i].label << "' and '" << spec.points[j].label << "' overlap";
            }
        }
    }
}

TEST(Plot, CrowdedLabelsDoNotOverlapEachOtherOrTheMarkers) {
    // The quality report's collision: LOD settings at nearly the same time and error, in two
    // series; and the ibl report's: several settings around the ringed default.
    PlotSpec quality{.title = "quality", .xLabel = "x", .yLabel = "y", .series = {"MSAA 1", "MSAA 4"}};
    quality.points = {{.x = 2.53, .y = 0.814, .label = "0/0.5/2 px"}, {.x = 2.55, .y = 0.815, .label = "4 px"},
                      {.x = 2.56, .y = 0.812, .label = "2 px", .series = 1}, {.x = 2.54, .y = 0.813, .label = "1 px", .series = 1},
                      {.x = 5.36, .y = 0.607, .label = "0 px", .series = 1}, {.x = 5.40, .y = 0.607, .label = "4 px", .series = 1},
                      {.x = 5.38, .y = 0.6075, .label = "2 px", .series = 1}};
    quality.highlight = 0;
    expectReadable(quality);

    PlotSpec ibl{.title = "ibl", .xLabel = "x", .yLabel = "y", .series = {"filtered", "plain", "cube"}};
    ibl.points = {{.x = 4.3, .y = 0.075, .label = "default"}, {.x = 4.1, .y = 0.078, .label = "32"},
                  {.x = 4.5, .y = 0.074, .label = "64", .series = 1}, {.x = 4.2, .y = 0.072, .label = "128", .series = 2},
                  {.x = 4.4, .y = 0.077, .label = "256", .series = 2}, {.x = 4.25, .y = 0.0745, .label = "sh9:16"},
                  {.x = 4.35, .y = 0.0755, .label = "lut 128x2048"}, {.x = 40, .y = 0.03, .label = ""},
                  {.x = 4.3, .y = 0.075, .label = "exactly on the default"}};
    ibl.highlight = 0;
    expectReadable(ibl);
}

TEST(Plot, WritesAPngOfTheRequestedSizeWithSomethingDrawn) {
    const candela::test::TempDir dir("candela_plot");
    const auto path = dir / "plot.png";
    PlotSpec spec{.title = "error vs time", .xLabel = "ms", .yLabel = "error", .series = {"a", "b"}};
    spec.points = {{.x = 10, .y = 0.5, .label = "8"}, {.x = 100, .y = 0.05, .label = "64", .series = 1},
                   {.x = 1000, .y = 0.04, .label = "512", .series = 1}};
    spec.highlight = 1;
    writeLogLogPlot(path, spec);
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &channels, 4);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(w, int(spec.width));
    EXPECT_EQ(h, int(spec.height));
    size_t red = 0;  // the ring around the default point
    for (int i = 0; i < w * h; ++i)
        red += pixels[i * 4] > 200 && pixels[i * 4 + 1] < 40 && pixels[i * 4 + 2] < 40;
    EXPECT_GT(red, 20u);
    stbi_image_free(pixels);
}

}  // namespace
}  // namespace candela::reports
