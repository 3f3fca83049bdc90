// Report plots: the Pareto front and the PNG writer.

#include "reports/plot.h"

#include "temp_dir.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>

namespace candela::io {
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

TEST(Plot, WritesAPngOfTheRequestedSizeWithSomethingDrawn) {
    const test::TempDir dir("candela_plot");
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
}  // namespace candela::io
