#pragma once
// A small scene whose meshes simplify, for the levels-of-detail tests: two bumpy 40 × 40 grids of
// quads far apart (two meshes: two draws of one range, one of the other), not yet prepared.

#include "scene/scene.h"

#include <cmath>

namespace candela::test {

inline scene::Scene bumpyScene(float bump = 0.3f) {
    scene::Scene s;
    for (int mesh = 0; mesh < 2; ++mesh) {
        const uint32_t base = uint32_t(s.vertices.size()), first = uint32_t(s.indices.size());
        for (int y = 0; y <= 40; ++y)
            for (int x = 0; x <= 40; ++x) {
                scene::Vertex v;
                v.position = glm::vec3(x, y, bump * std::sin(0.4f * float(x + mesh)) * std::cos(0.3f * float(y)));
                v.normal = glm::vec3(0, 0, 1);
                s.vertices.push_back(v);
            }
        for (uint32_t y = 0; y < 40; ++y)
            for (uint32_t x = 0; x < 40; ++x) {
                const uint32_t a = base + y * 41 + x;
                s.indices.insert(s.indices.end(), {a, a + 1, a + 41, a + 1, a + 42, a + 41});
            }
        scene::Draw draw;
        draw.firstIndex = first;
        draw.indexCount = uint32_t(s.indices.size()) - first;
        s.draws.push_back(draw);
        if (mesh == 0) s.draws.push_back(draw);
    }
    s.materials.emplace_back();
    return s;
}

}  // namespace candela::test
