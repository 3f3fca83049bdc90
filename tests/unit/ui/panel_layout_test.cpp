// Where the viewer's panels go (ui/panel_layout.h): two columns sized in font sizes, the scene
// centred between them.
#include "ui/panel_layout.h"

#include <gtest/gtest.h>

namespace candela::ui {
namespace {

TEST(PanelLayout, ColumnsAreSizedByTheFontAndTheSceneIsCentredBetweenThem) {
    for (const auto& [width, height] : {std::pair(1280.0f, 720.0f), std::pair(1920.0f, 1080.0f)}) {
        const PanelLayout layout = layoutPanels(width, height, 13.0f);
        EXPECT_FLOAT_EQ(layout.left.x, 0.0f);
        EXPECT_FLOAT_EQ(layout.left.width, kLeftColumnEms * 13.0f);
        EXPECT_FLOAT_EQ(layout.right.width, kRightColumnEms * 13.0f);
        EXPECT_FLOAT_EQ(layout.right.right(), width);
        EXPECT_FLOAT_EQ(layout.left.height, height);
        EXPECT_FLOAT_EQ(layout.right.height, height);
        EXPECT_FLOAT_EQ(layout.sceneLeft, layout.left.right());
        EXPECT_FLOAT_EQ(layout.sceneRight, layout.right.x);
        EXPECT_GE(layout.sceneRight - layout.sceneLeft, width / 3.0f);
        // The projection's centre (NDC 0 shifted by lensShiftX) is the middle of the scene's range.
        const float centre = (layout.lensShiftX(width) + 1.0f) * 0.5f * width;
        EXPECT_NEAR(centre, (layout.sceneLeft + layout.sceneRight) * 0.5f, 1e-3f);
        EXPECT_FLOAT_EQ(layout.sceneAspect(height), (layout.sceneRight - layout.sceneLeft) / height);
    }
    // A larger font widens the columns with it.
    EXPECT_FLOAT_EQ(layoutPanels(1920.0f, 1080.0f, 16.0f).left.width, kLeftColumnEms * 16.0f);
}

TEST(PanelLayout, NarrowWindowsKeepAThirdForTheScene) {
    const PanelLayout layout = layoutPanels(600.0f, 400.0f, 13.0f);
    EXPECT_NEAR(layout.sceneRight - layout.sceneLeft, 200.0f, 1e-3f);
    EXPECT_NEAR(layout.left.width / layout.right.width, kLeftColumnEms / kRightColumnEms, 1e-5f);
    EXPECT_FLOAT_EQ(layout.right.right(), 600.0f);
    // An empty (minimized) window has no room: nothing is negative or infinite.
    const PanelLayout empty = layoutPanels(0.0f, 0.0f, 13.0f);
    EXPECT_FLOAT_EQ(empty.left.width, 0.0f);
    EXPECT_FLOAT_EQ(empty.lensShiftX(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(empty.sceneAspect(0.0f), 1.0f);
}

}  // namespace
}  // namespace candela::ui
