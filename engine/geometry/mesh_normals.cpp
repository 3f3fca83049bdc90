#include "geometry/mesh_normals.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace candela::geometry {

glm::vec3 normalizeOrZero(const glm::vec3& v) {
    const float largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (largest == 0.0f) return v;
    const glm::vec3 scaled = v / largest;  // largest component ±1: dot in [1, 3]
    return scaled / std::sqrt(glm::dot(scaled, scaled));
}

glm::vec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    // Double precision: millimetre-sized triangles would underflow the float cross product.
    const glm::dvec3 n = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
    const double length = glm::length(n);
    if (!(length > 0.0) || !std::isfinite(length)) return glm::vec3(0.0f, 0.0f, 1.0f);
    return glm::vec3(n / length);
}

void makeFlatNormals(std::vector<scene::Vertex>& vertices, std::vector<uint32_t>& indices, std::vector<uint32_t>& origin) {
    const size_t triangleCount = indices.size() / 3;
    std::vector<scene::Vertex> flat;
    flat.reserve(triangleCount * 3);
    std::vector<uint32_t> flatOrigin;
    flatOrigin.reserve(triangleCount * 3);
    std::vector<uint32_t> flatIndices(triangleCount * 3);
    for (size_t t = 0; t < triangleCount; ++t) {
        const scene::Vertex* corner[3] = {&vertices[indices[3 * t]], &vertices[indices[3 * t + 1]], &vertices[indices[3 * t + 2]]};
        const glm::vec3 n = faceNormal(corner[0]->position, corner[1]->position, corner[2]->position);
        for (size_t i = 0; i < 3; ++i) {
            scene::Vertex v = *corner[i];
            v.normal = n;
            v.tangent = scene::Vertex{}.tangent;
            flatIndices[3 * t + i] = uint32_t(flat.size());
            flat.push_back(v);
            flatOrigin.push_back(origin[indices[3 * t + i]]);
        }
    }
    vertices = std::move(flat);
    origin = std::move(flatOrigin);
    indices = std::move(flatIndices);
}

}  // namespace candela::geometry
