// Mouse control of the orbit camera (ui/orbit_controls.h) and picking (pose/picking.h).
#include "assets/builtin_scenes.h"
#include "pose/picking.h"
#include "pose/shown_points.h"
#include "ui/orbit_controls.h"

#include <gtest/gtest.h>

namespace candela::ui {
namespace {

scene::OrbitCamera camera() {
    scene::OrbitCamera c;
    c.target = glm::vec3(1.0f, 2.0f, 3.0f);
    c.radius = 10.0f;
    c.thetaDegrees = 30.0f;
    c.phiDegrees = 60.0f;
    return c;
}

TEST(OrbitControls, RightDragRotatesAboutTheTarget) {
    scene::OrbitCamera c = camera();
    ui::applyPointer(c, {.delta = {40.0f, -20.0f}, .rotate = true, .viewportHeight = 500.0f}, {.rotateDegreesPerPixel = 0.25f});
    EXPECT_FLOAT_EQ(c.thetaDegrees, 20.0f);
    EXPECT_FLOAT_EQ(c.phiDegrees, 65.0f);
    EXPECT_FLOAT_EQ(glm::length(c.eye() - c.target), 10.0f);
    // The polar angle stops short of the poles.
    ui::applyPointer(c, {.delta = {0.0f, 10000.0f}, .rotate = true}, {});
    EXPECT_FLOAT_EQ(c.phiDegrees, 1.0f);
}

TEST(OrbitControls, ScrollZoomsAndMiddleDragPans) {
    scene::OrbitCamera c = camera();
    ui::applyPointer(c, {.scroll = 2.0f}, {.zoomPerStep = 0.1f});
    EXPECT_NEAR(c.radius, 10.0f * 0.81f, 1e-5f);
    ui::applyPointer(c, {.scroll = -2.0f}, {.zoomPerStep = 0.1f});
    EXPECT_NEAR(c.radius, 10.0f, 1e-4f);

    // Dragging right by the viewport's height moves the target left by the visible height at the
    // target's distance; the view direction is unchanged.
    scene::OrbitCamera p = camera();
    const glm::vec3 forward = glm::normalize(p.target - p.eye());
    const float visible = 2.0f * p.radius * std::tan(glm::radians(p.fovYDegrees) * 0.5f);
    ui::applyPointer(p, {.delta = {500.0f, 0.0f}, .pan = true, .viewportHeight = 500.0f}, {});
    const glm::vec3 moved = p.target - camera().target;
    EXPECT_NEAR(glm::length(moved), visible, 1e-4f);
    EXPECT_NEAR(glm::dot(moved, forward), 0.0f, 1e-5f);
    EXPECT_NEAR(moved.y, 0.0f, 1e-5f);  // right is horizontal for an upright camera
    EXPECT_NEAR(glm::dot(glm::normalize(p.target - p.eye()), forward), 1.0f, 1e-6f);
}

TEST(OrbitControls, SettingTheEyeKeepsTheTarget) {
    scene::OrbitCamera c = camera();
    const glm::vec3 eye(4.0f, 6.0f, -2.0f);
    ui::setEye(c, eye);
    EXPECT_NEAR(glm::length(c.eye() - eye), 0.0f, 1e-5f);
    EXPECT_EQ(c.target, camera().target);
    ui::setEye(c, c.target);  // degenerate: unchanged
    EXPECT_NEAR(glm::length(c.eye() - eye), 0.0f, 1e-5f);
}

TEST(Picking, RayThroughTheCentreHitsTheMiddleSphere) {
    const scene::Scene grid = assets::makeSphereGrid();
    const scene::OrbitCamera c = scene::frame(pose::shownPoints(grid, nullptr), {.aspect = 16.0f / 9.0f, .directions = {{0.0f, 75.0f}}});
    const scene::ViewSetup view = c.view(16.0f / 9.0f);
    const pose::Ray ray = pose::viewRay(view, {0.0f, 0.0f});
    EXPECT_NEAR(glm::dot(ray.direction, glm::normalize(c.target - c.eye())), 1.0f, 1e-5f);
    const std::optional<pose::Pick> pick = pose::pickDraw(grid, ray);
    ASSERT_TRUE(pick.has_value());
    EXPECT_EQ(grid.draws[pick->draw].material, 24u);
    EXPECT_LT(pick->distance, c.radius);
    EXPECT_FALSE(pose::pickDraw(grid, pose::viewRay(view, {0.99f, -0.99f})).has_value());
}

TEST(Picking, NearestOfTwoOverlappingTrianglesAndBothFaces) {
    scene::Scene s;
    for (float z : {0.0f, -2.0f})
        for (glm::vec2 xy : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(0, 1)}) s.vertices.push_back({.position = {xy, z}});
    s.indices = {0, 1, 2, 5, 4, 3};  // the far one wound the other way
    for (uint32_t d = 0; d < 2; ++d) {
        scene::Draw draw{.firstIndex = 3 * (1 - d), .indexCount = 3, .material = d};
        for (uint32_t i = 0; i < 3; ++i) draw.bounds.extend(s.vertices[s.indices[draw.firstIndex + i]].position);
        s.draws.push_back(draw);
    }
    const std::optional<pose::Pick> pick = pose::pickDraw(s, {{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}});
    ASSERT_TRUE(pick.has_value());
    EXPECT_EQ(s.draws[pick->draw].material, 1u);  // draw 1 holds the near triangle
    EXPECT_FLOAT_EQ(pick->distance, 5.0f);
    // From behind, the far triangle is the nearest.
    const std::optional<pose::Pick> back = pose::pickDraw(s, {{0.0f, 0.0f, -5.0f}, {0.0f, 0.0f, 1.0f}});
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(s.draws[back->draw].material, 0u);
}

}  // namespace
}  // namespace candela::ui
