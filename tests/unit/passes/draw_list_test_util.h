#pragma once
// Hand-made draws and a view for the tests of the draw list and what is made of it
// (draw_list_test.cpp, shading_summary_test.cpp): no vertices, world bounds only.

#include "scene/camera.h"
#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdint>

namespace candela::passes {

// A unit box's draw of `material` at `centre` (world bounds only: the list reads no vertices).
inline scene::Draw drawAt(uint32_t material, glm::vec3 centre, uint32_t indexCount = 36) {
    scene::Draw d;
    d.material = material;
    d.indexCount = indexCount;
    d.world = glm::translate(glm::mat4(1.0f), centre);
    d.bounds = {centre - 0.5f, centre + 0.5f};
    d.localBounds = {glm::vec3(-0.5f), glm::vec3(0.5f)};
    return d;
}

// The eye at the origin looking down −Z (90°, square).
inline scene::ViewSetup lookingDownMinusZ() {
    scene::ViewSetup v;
    v.view = glm::lookAt(glm::vec3(0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    v.projection = scene::perspectiveReverseZ(glm::radians(90.0f), 1.0f, 0.1f);
    v.viewProjection = v.projection * v.view;
    return v;
}

}  // namespace candela::passes
