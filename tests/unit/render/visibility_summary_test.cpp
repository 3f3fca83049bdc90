// The visibility path's summary in words (render/visibility_summary.h): the --explain line of a
// visibility frame at one and at four samples.
#include "render/visibility_summary.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

VisibilitySummary grid(uint32_t samples) {
    return {.draws = 49, .width = 640, .height = 360, .samples = samples, .tiles = 3600, .tileWidth = 8, .tileHeight = 8,
            .lists = {{"pbr+ibl-cube", 0, 48}, {"pbr+ibl-cube+normal-map", 1, 1}}};
}

TEST(VisibilitySummary, OneSampleLine) {
    EXPECT_EQ(explainVisibility(grid(1)),
              "shading path: visibility — 49 opaque and masked draws into a 640×360 visibility image, classified in 3600 "
              "tiles of 8×8; one compute dispatch per shading list (variant × texture set): pbr+ibl-cube/textures0 ×48 "
              "pbr+ibl-cube+normal-map/textures1 ×1");
}

TEST(VisibilitySummary, SeveralSamplesNameThemAndTheResolveInTheShading) {
    EXPECT_EQ(explainVisibility(grid(4)),
              "shading path: visibility — 49 opaque and masked draws into a 640×360 4-sample visibility image, "
              "classified in 3600 tiles of 8×8; one compute dispatch per shading list (variant × texture set): "
              "pbr+ibl-cube/textures0 ×48 pbr+ibl-cube+normal-map/textures1 ×1; then, on triangle edges, each further "
              "distinct triangle of a pixel's samples (the resolve in the shading)");
}

}  // namespace
}  // namespace candela
