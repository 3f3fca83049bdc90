#include "assets/builtin_scenes.h"

#include "geometry/mesh_lod.h"
#include "geometry/mesh_optimize.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace candela::assets {

std::pair<uint32_t, uint32_t> appendUvSphere(scene::Scene& scene, float radius, uint32_t sectors, uint32_t stacks) {
    const auto base = static_cast<uint32_t>(scene.vertices.size());
    const auto firstIndex = static_cast<uint32_t>(scene.indices.size());
    for (uint32_t i = 0; i <= stacks; ++i) {
        const float v = static_cast<float>(i) / static_cast<float>(stacks);
        const float polar = v * glm::pi<float>();  // 0 at +Y
        for (uint32_t j = 0; j <= sectors; ++j) {
            const float u = static_cast<float>(j) / static_cast<float>(sectors);
            const float azimuth = u * glm::two_pi<float>();
            const glm::vec3 n(std::sin(polar) * std::sin(azimuth), std::cos(polar), std::sin(polar) * std::cos(azimuth));
            scene::Vertex vertex;
            vertex.position = radius * n;
            vertex.normal = n;
            // d(position)/d(u) points along increasing azimuth; at the poles use the limit direction.
            vertex.tangent = glm::vec4(std::cos(azimuth), 0.0f, -std::sin(azimuth), 1.0f);
            vertex.uv0 = vertex.uv1 = glm::vec2(u, v);
            scene.vertices.push_back(vertex);
        }
    }
    for (uint32_t i = 0; i < stacks; ++i)
        for (uint32_t j = 0; j < sectors; ++j) {
            const uint32_t a = base + i * (sectors + 1) + j, b = a + sectors + 1;
            // Counter-clockwise seen from outside; the degenerate triangles at the poles are skipped.
            if (i != 0) scene.indices.insert(scene.indices.end(), {a, b, a + 1});
            if (i != stacks - 1) scene.indices.insert(scene.indices.end(), {a + 1, b, b + 1});
        }
    return {firstIndex, static_cast<uint32_t>(scene.indices.size()) - firstIndex};
}

scene::Scene makeSphereGrid(uint32_t side, bool materialPerSphere) {
    constexpr int kRows = 7, kColumns = 7;  // the materials
    constexpr float kSpacing = 2.5f;
    if (side == 0) throw std::invalid_argument("makeSphereGrid: a grid of 0 spheres");
    scene::Scene scene;
    scene.source = side == 7 ? "built-in: sphere grid" : "built-in: sphere grid " + std::to_string(side) + "x" + std::to_string(side);
    const auto [firstIndex, indexCount] = appendUvSphere(scene, 1.0f, 64, 32);
    // Its levels of detail: coarser tessellations of the same sphere (the simplifier would stop at
    // about 440 triangles: it locks the poles' coincident vertices), each with its measured
    // distance from the full detail. Each step about doubles the error (the first, 32 × 16, is
    // 0.33 px at the default view's 35 px per metre); together they add 47% to its indices (the
    // budget is 50%).
    scene::LodChain chain;
    chain.levels.push_back({firstIndex, indexCount, 0.0f});
    const std::vector<uint32_t> full(scene.indices.begin() + firstIndex, scene.indices.end());  // the array grows below
    for (const auto& [sectors, stacks] : {std::pair{32u, 16u}, {24u, 12u}, {16u, 8u}, {12u, 6u}, {8u, 4u}}) {
        const auto [levelFirst, levelCount] = appendUvSphere(scene, 1.0f, sectors, stacks);
        const std::span<const uint32_t> level(scene.indices.data() + levelFirst, levelCount);
        chain.levels.push_back({levelFirst, levelCount, std::max(geometry::surfaceDeviation(scene.vertices, full, level), chain.levels.back().error)});
    }
    scene.lodChains.push_back(std::move(chain));
    scene::Aabb sphereBounds;
    sphereBounds.extend(glm::vec3(-1.0f));
    sphereBounds.extend(glm::vec3(1.0f));
    for (int row = 0; row < kRows; ++row)
        for (int column = 0; column < kColumns; ++column) {
            scene::Material material;
            material.name = "metallic " + std::to_string(column) + "/6, roughness " + std::to_string(row) + "/6";
            material.baseColorFactor = glm::vec4(0.5f, 0.0f, 0.0f, 1.0f);
            material.metallicFactor = static_cast<float>(column) / (kColumns - 1);
            // Roughness 0 would make a point light's highlight a delta: start at 0.05 as the original did.
            material.roughnessFactor = glm::clamp(static_cast<float>(row) / (kRows - 1), 0.05f, 1.0f);
            scene.materials.push_back(material);
        }
    const std::vector<scene::Material> cells = std::move(scene.materials);
    scene.materials = materialPerSphere ? std::vector<scene::Material>{} : cells;
    for (uint32_t row = 0; row < side; ++row)
        for (uint32_t column = 0; column < side; ++column) {
            scene::Draw draw;
            draw.firstIndex = firstIndex;
            draw.indexCount = indexCount;
            // Sphere (row, column) wears the material of its part of the 7 × 7 grid, or a copy of
            // it in a colour of its own.
            draw.material = row * kRows / side * kColumns + column * kColumns / side;
            if (materialPerSphere) {
                scene::Material own = cells[draw.material];
                draw.material = static_cast<uint32_t>(scene.materials.size());
                own.name = "sphere " + std::to_string(draw.material);
                own.baseColorFactor = glm::vec4(0.05f, 0.05f, 0.05f, 1.0f);
                own.baseColorFactor[draw.material % 3] = 0.8f;
                scene.materials.push_back(std::move(own));
            }
            const float centre = (float(side) - 1.0f) / 2.0f;
            const glm::vec3 offset((float(column) - centre) * kSpacing, (float(row) - centre) * kSpacing, 0.0f);
            draw.world = glm::translate(glm::mat4(1.0f), offset);
            draw.localBounds = sphereBounds;
            draw.lod = 0;
            draw.bounds.extend(sphereBounds.min + offset);
            draw.bounds.extend(sphereBounds.max + offset);
            scene.bounds.extend(draw.bounds);
            scene.draws.push_back(draw);
        }
    // In front of the grid's corners; a larger grid gets them further out and brighter by the
    // square of the distance (the same irradiance where the 7 × 7 grid has its spheres).
    const float reach = float(side) / 7.0f;
    for (const glm::vec2 corner : {glm::vec2(-10, 10), glm::vec2(10, 10), glm::vec2(-10, -10), glm::vec2(10, -10)}) {
        scene::Light light;
        light.type = scene::LightType::Point;
        light.intensity = 300.0f * reach * reach;
        light.position = glm::vec3(corner, 10.0f) * reach;
        scene.lights.push_back(light);
    }
    // A chart: framed head-on, rows and columns along the image's, every sphere the same size.
    scene.framingAngles = glm::vec2(0.0f, 90.0f);
    geometry::prepareGeometry(scene);
    return scene;
}

}  // namespace candela::assets
