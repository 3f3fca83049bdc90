#pragma once
// KHR_texture_transform as a matrix, with the rotation direction the sample model
// TextureTransformTest, three.js and CesiumGltf agree on:
//   u' = offset.u + ( cos r · su·u + sin r · sv·v)
//   v' = offset.v + (−sin r · su·u + cos r · sv·v)
// (counter-clockwise in glTF's top-left-origin texture space). Shaders should use this matrix
// rather than rebuild the rotation, so the CPU (tangent generation) and the GPU agree.

#include "scene/scene.h"

#include <glm/mat3x3.hpp>

#include <cmath>

namespace candela::scene {

// Column-major 3×3 affine matrix M with (u', v', 1) = M · (u, v, 1).
inline glm::mat3 textureTransformMatrix(const TextureTransform& t) {
    const float c = std::cos(t.rotation), s = std::sin(t.rotation);
    return glm::mat3(c * t.scale.x, -s * t.scale.x, 0.0f,  // column 0: image of (1, 0)
                     s * t.scale.y, c * t.scale.y, 0.0f,   // column 1: image of (0, 1)
                     t.offset.x, t.offset.y, 1.0f);
}

inline glm::vec2 applyTextureTransform(const TextureTransform& t, const glm::vec2& uv) {
    return glm::vec2(textureTransformMatrix(t) * glm::vec3(uv, 1.0f));
}

}  // namespace candela::scene
