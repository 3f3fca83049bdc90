#include "pose/picking.h"

#include "pose/skinning.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela::pose {

namespace {

// Slab test; returns the entry distance or nullopt.
std::optional<float> hitBox(const scene::Aabb& box, const Ray& ray) {
    float near = 0.0f, far = std::numeric_limits<float>::max();
    for (int axis = 0; axis < 3; ++axis) {
        const float inverse = 1.0f / ray.direction[axis];  // ±inf for axis-parallel rays: fine
        float t0 = (box.min[axis] - ray.origin[axis]) * inverse;
        float t1 = (box.max[axis] - ray.origin[axis]) * inverse;
        if (t0 > t1) std::swap(t0, t1);
        if (std::isnan(t0) || std::isnan(t1)) continue;  // origin on the slab's plane, parallel ray
        near = std::max(near, t0);
        far = std::min(far, t1);
        if (near > far) return std::nullopt;
    }
    return near;
}

// Möller–Trumbore, both faces; distance along the ray or nullopt.
std::optional<float> hitTriangle(const Ray& ray, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(ray.direction, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) return std::nullopt;
    const float inverse = 1.0f / det;
    const glm::vec3 s = ray.origin - a;
    const float u = glm::dot(s, p) * inverse;
    if (u < 0.0f || u > 1.0f) return std::nullopt;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(ray.direction, q) * inverse;
    if (v < 0.0f || u + v > 1.0f) return std::nullopt;
    const float t = glm::dot(e2, q) * inverse;
    if (!(t > 0.0f)) return std::nullopt;
    return t;
}

}  // namespace

Ray viewRay(const scene::ViewSetup& view, const glm::vec2& ndc) {
    const glm::mat4 inverse = glm::inverse(view.viewProjection);
    // Reverse-Z: depth 1 at the near plane, 0.5 further along the same ray.
    const glm::vec4 nearPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec4 farPoint = inverse * glm::vec4(ndc, 0.5f, 1.0f);
    const glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w, b = glm::vec3(farPoint) / farPoint.w;
    return {view.eye, glm::normalize(b - a)};
}

namespace {

// The nearest hit among `draws`; `positions(d)` gives draw d's vertex positions in its draw space
// (indexable by the scene's absolute indices minus `base(d)`).
template <typename Positions>
std::optional<Pick> pick(const scene::Scene& scene, std::span<const scene::Draw> draws, const Ray& ray, Positions&& positions) {
    std::optional<Pick> best;
    for (uint32_t d = 0; d < draws.size(); ++d) {
        const scene::Draw& draw = draws[d];
        if (draw.hidden || draw.topology != scene::Topology::Triangles) continue;  // a ray hits no point or line
        const std::optional<float> box = hitBox(draw.bounds, ray);
        if (!box || (best && *box > best->distance)) continue;
        const std::pair<std::span<const scene::Vertex>, uint32_t> range = positions(d);
        const std::span<const scene::Vertex> vertices = range.first;  // (no structured binding: lambdas capture it)
        const uint32_t base = range.second;
        for (uint32_t instance = 0; instance < std::max(draw.instanceCount, 1u); ++instance) {
            const glm::mat4 m = draw.instanceCount ? draw.world * scene.instances[draw.firstInstance + instance] : draw.world;
            for (uint32_t i = 0; i + 2 < draw.indexCount; i += 3) {
                const uint32_t* tri = scene.indices.data() + draw.firstIndex + i;
                if (tri[0] < base || tri[1] < base || tri[2] < base || tri[0] - base >= vertices.size() ||
                    tri[1] - base >= vertices.size() || tri[2] - base >= vertices.size())
                    continue;
                const auto world = [&](uint32_t v) { return glm::vec3(m * glm::vec4(vertices[v - base].position, 1.0f)); };
                const std::optional<float> t = hitTriangle(ray, world(tri[0]), world(tri[1]), world(tri[2]));
                if (t && (!best || *t < best->distance)) best = Pick{d, *t};
            }
        }
    }
    return best;
}

}  // namespace

std::optional<Pick> pickDraw(const scene::Scene& scene, const Ray& ray) {
    return pick(scene, scene.draws, ray, [&](uint32_t) { return std::pair{std::span<const scene::Vertex>(scene.vertices), 0u}; });
}

std::optional<Pick> pickDraw(const scene::Scene& scene, const ScenePose& pose, const Ray& ray) {
    const std::vector<uint32_t> deformed = pose.deformedDraws();
    std::vector<scene::Vertex> posed;  // the deformed vertices of the draw being tested
    static const std::vector<glm::dmat4> kNoJoints;
    return pick(scene, pose.draws(), ray, [&](uint32_t d) {
        if (!std::binary_search(deformed.begin(), deformed.end(), d))
            return std::pair{std::span<const scene::Vertex>(scene.vertices), 0u};
        const scene::Draw& draw = pose.draws()[d];
        posed = deformVertices(scene, draw, pose.weights(draw), draw.skin >= 0 ? pose.jointMatrices(uint32_t(draw.skin)) : kNoJoints);
        return std::pair{std::span<const scene::Vertex>(posed), scene.deformations[size_t(draw.deformation)].firstVertex};
    });
}

}  // namespace candela::pose
