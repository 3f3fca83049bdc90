#include "scene/framing.h"

#include <algorithm>
#include <cmath>

namespace candela::scene {

OrbitCamera frame(const PointSource& points, const FramingRequest& request) {
    const glm::vec2 first = request.directions.empty() ? glm::vec2(0.0f, kDefaultOrbitPolarDegrees) : request.directions[0];
    OrbitCamera camera;
    camera.thetaDegrees = first.x;
    camera.phiDegrees = first.y;
    camera.fovYDegrees = request.fovYDegrees.value_or(kFramingFovYDegrees);

    Aabb box;
    points([&](std::span<const glm::vec3> batch) {
        for (const glm::vec3& p : batch) box.extend(p);
    });
    if (!box.valid()) return camera;
    const glm::vec3 target = 0.5f * (box.min + box.max);
    float radius = 0.0f;
    points([&](std::span<const glm::vec3> batch) {
        for (const glm::vec3& p : batch) radius = std::max(radius, glm::length(p - target));
    });
    radius = std::max(radius, 1e-6f * std::max(1.0f, glm::length(target)));
    camera.target = target;
    camera.radius = radius / std::sin(glm::radians(0.5f * kFramingConeDegrees));
    camera.znear = camera.radius * 1e-3f;
    if (request.fovYDegrees) return camera;
    camera.fovYDegrees = kFramingConeDegrees;

    // Per direction, the view's rotation (radius 1, target at the origin: the rotation does not
    // depend on them). A point at view-space offset q from the target is at depth d − q.z > 0 (every
    // point is within R of the target, and d > R).
    std::vector<glm::mat3> rotations;
    for (const glm::vec2& direction : request.directions.empty() ? std::vector<glm::vec2>{first} : request.directions) {
        OrbitCamera unit;
        unit.thetaDegrees = direction.x;
        unit.phiDegrees = direction.y;
        unit.radius = 1.0f;
        rotations.emplace_back(unit.view(1.0f).view);
    }
    const float d = camera.radius;
    float tanX = 0.0f, tanY = 0.0f;  // the largest |x| / depth and |y| / depth over points and directions
    points([&](std::span<const glm::vec3> batch) {
        for (const glm::mat3& rotation : rotations)
            for (const glm::vec3& p : batch) {
                const glm::vec3 q = rotation * (p - target);
                const float depth = d - q.z;
                tanX = std::max(tanX, std::abs(q.x) / depth);
                tanY = std::max(tanY, std::abs(q.y) / depth);
            }
    });
    const float needed = std::max(tanY, tanX / std::max(request.aspect, 1e-6f)) / kSilhouetteSpan;
    // (A silhouette with no extent — a point seen from anywhere, a line end-on, up to rounding — keeps
    // the cone's; at most 150° for a very narrow image.)
    if (needed > 1e-4f * std::tan(glm::radians(0.5f * kFramingConeDegrees))) camera.fovYDegrees = glm::degrees(2.0f * std::atan(std::min(needed, std::tan(glm::radians(75.0f)))));
    return camera;
}

PointSource pointsOf(std::vector<glm::vec3> points) {
    return [points = std::move(points)](const PointBatch& visit) { visit(points); };
}

}  // namespace candela::scene
