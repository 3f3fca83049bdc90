#include "pose/node_placement.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace candela::pose {
namespace {

bool fitsFloat(double v) { return std::isfinite(v) && std::abs(v) <= double(FLT_MAX); }

}  // namespace

Placement placeDraw(scene::Draw& draw, const glm::dmat4& world, const glm::vec3& reach, std::span<const glm::mat4> instances) {
    draw.hidden = true;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!fitsFloat(world[c][r])) return Placement::BeyondFloat;
    const glm::mat4 worldF(world);
    // In double from the float matrix the GPU gets: in float the determinant overflows for scales
    // near 1e13, which are valid.
    double det = glm::determinant(glm::dmat3(glm::mat3(worldF)));
    if (det == 0.0 || !std::isfinite(det)) return Placement::Singular;
    if (!instances.empty()) det *= glm::determinant(glm::dmat3(glm::mat3(instances[0])));
    scene::Aabb bounds;
    const glm::dvec3 lo = glm::dvec3(draw.localBounds.min) - glm::dvec3(reach);
    const glm::dvec3 hi = glm::dvec3(draw.localBounds.max) + glm::dvec3(reach);
    const size_t copies = std::max<size_t>(instances.size(), 1);
    for (size_t i = 0; i < copies; ++i) {
        const glm::dmat4 m = instances.empty() ? world : world * glm::dmat4(instances[i]);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
            const glm::dvec3 w(m * glm::dvec4(p, 1.0));
            if (!fitsFloat(w.x) || !fitsFloat(w.y) || !fitsFloat(w.z)) return Placement::BeyondFloat;
            bounds.extend(glm::vec3(w));
        }
    }
    draw.world = worldF;
    draw.flipWinding = det < 0.0;
    draw.bounds = bounds;
    draw.hidden = false;
    return Placement::Placed;
}

Placement placeSkinnedDraw(scene::Draw& draw, const scene::Aabb& bounds) {
    draw.world = glm::mat4(1.0f);
    draw.flipWinding = false;
    draw.bounds = bounds;
    const bool fits = fitsFloat(bounds.min.x) && fitsFloat(bounds.min.y) && fitsFloat(bounds.min.z) &&
                      fitsFloat(bounds.max.x) && fitsFloat(bounds.max.y) && fitsFloat(bounds.max.z);
    draw.hidden = !bounds.valid() || !fits;
    return !fits ? Placement::BeyondFloat : bounds.valid() ? Placement::Placed : Placement::Singular;
}

void placeLight(scene::Light& light, const glm::dmat4& world) {
    light.position = glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dvec3 direction = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0);
    const double length = glm::length(direction);
    light.direction = length > 0.0 && std::isfinite(length) ? glm::vec3(direction / length) : glm::vec3(0.0f, 0.0f, -1.0f);
}

bool placeCamera(scene::Camera& camera, const glm::dmat4& world) {
    glm::dmat4 m = world;
    for (int c = 0; c < 3; ++c) {
        const double length = glm::length(glm::dvec3(m[c]));
        if (!(length > 0.0) || !std::isfinite(length)) return false;
        m[c] /= length;
    }
    camera.world = glm::mat4(m);
    return true;
}

}  // namespace candela::pose
