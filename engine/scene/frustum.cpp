#include "scene/frustum.h"

#include <cmath>

namespace candela::scene {

Frustum::Frustum(const glm::mat4& m) {
    // Row i of the matrix (glm is column-major: m[column][row]).
    const auto row = [&](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    const glm::vec4 x = row(0), y = row(1), z = row(2), w = row(3);
    // Inside ⇔ plane · (p, 1) ≥ 0 for each of: x ≥ −w, x ≤ w, y ≥ −w, y ≤ w, z ≥ 0, z ≤ w.
    for (const glm::vec4& plane : {w + x, w - x, w + y, w - y, z, w - z}) {
        const float length = glm::length(glm::vec3(plane));
        // The infinite far plane of a reverse-Z projection has no normal (z_clip = znear: always
        // inside); a plane of a degenerate matrix neither. Neither culls anything.
        if (!(length > 0.0f) || !std::isfinite(length)) continue;
        mPlanes[mCount++] = plane / length;
    }
}

bool Frustum::intersects(const Aabb& box) const {
    for (uint32_t i = 0; i < mCount; ++i) {
        const glm::vec3 n(mPlanes[i]);
        // The corner furthest along the inward normal: if even it is outside, all of the box is.
        const glm::vec3 corner(n.x >= 0.0f ? box.max.x : box.min.x, n.y >= 0.0f ? box.max.y : box.min.y,
                               n.z >= 0.0f ? box.max.z : box.min.z);
        if (glm::dot(n, corner) + mPlanes[i].w < 0.0f) return false;
    }
    return true;
}

}  // namespace candela::scene
