// What a pose animates besides its nodes, in words (render/posed_summary.h): the --explain line
// names only what animates, with the buffers the CPU writes for it.
#include "render/posed_summary.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

TEST(PosedSummary, NothingAnimatedSaysNothing) {
    EXPECT_TRUE(PosedSummary{}.empty());
    EXPECT_EQ(explainPosed({}), "");
}

TEST(PosedSummary, OneMaterialNamesItsBuffer) {
    EXPECT_EQ(explainPosed({.materials = 1}),
              "animated properties (KHR_animation_pointer), written by the CPU per frame: 1 material (posed_materials)");
}

TEST(PosedSummary, EveryKindInOrderWithPluralsAndBuffers) {
    EXPECT_EQ(explainPosed({.materials = 2, .materialLayers = true, .lights = 1, .lightsWritten = true, .cameras = 3}),
              "animated properties (KHR_animation_pointer), written by the CPU per frame: 2 materials (posed_materials, "
              "posed_material_layers), 1 light (posed_lights), 3 cameras (the view of a glTF camera follows)");
}

TEST(PosedSummary, LightsNotDrawnSaySo) {
    EXPECT_EQ(explainPosed({.lights = 2}),
              "animated properties (KHR_animation_pointer), written by the CPU per frame: 2 lights (not drawn: "
              "--scene-lights off)");
}

}  // namespace
}  // namespace candela
