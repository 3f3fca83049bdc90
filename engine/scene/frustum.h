#pragma once
// View-frustum culling on the CPU: the planes of a view-projection matrix and a conservative test
// of world-space boxes against them (a box is culled only when it lies wholly outside one plane).
// Works for the renderer's reverse-Z projections (scene/camera.h), including the infinite far
// plane, whose clip-space "plane" z ≥ 0 holds everywhere in front of the eye and is left out.

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>

namespace candela::scene {

class Frustum {
public:
    // The frustum of `viewProjection` (Vulkan clip space: −w ≤ x, y ≤ w, 0 ≤ z ≤ w). Planes whose
    // normal is zero (the infinite far plane) are dropped.
    explicit Frustum(const glm::mat4& viewProjection);

    // Whether `box` (world space, valid) may be visible: false only when it lies wholly on the
    // outside of some plane. Boxes straddling a plane, or near a corner outside two planes, count
    // as visible (the test is conservative, never wrong the other way).
    bool intersects(const Aabb& box) const;

    uint32_t planeCount() const { return mCount; }

private:
    std::array<glm::vec4, 6> mPlanes{};  // xyz normal pointing inside, w offset: inside ⇔ n·p + w ≥ 0
    uint32_t mCount = 0;
};

}  // namespace candela::scene
