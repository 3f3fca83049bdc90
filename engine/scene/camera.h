#pragma once
// Cameras: the orbit camera of the original project (target, angles, distance), glTF cameras, and
// reverse-Z projections with an infinite far plane (depth 1 at the near plane → 0 at infinity), so
// scenes from millimetres to kilometres keep depth precision. Vulkan clip space: y down, z in [0,1].

#include "scene/scene.h"

#include <glm/glm.hpp>

namespace candela::scene {

struct ViewSetup {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f};
    glm::vec3 eye{0.0f};
    float znear = 0.1f;
};

// Perspective, reverse-Z, infinite far plane. fovY in radians, aspect = width / height.
glm::mat4 perspectiveReverseZ(float fovY, float aspect, float znear);
// Perspective, reverse-Z, finite far plane (glTF cameras with zfar).
glm::mat4 perspectiveReverseZ(float fovY, float aspect, float znear, float zfar);
// Orthographic, reverse-Z (depth 1 at znear, 0 at zfar). xmag, ymag: half extents.
glm::mat4 orthographicReverseZ(float xmag, float ymag, float znear, float zfar);

struct OrbitCamera {
    glm::vec3 target{0.0f};
    float thetaDegrees = 0.0f;   // azimuth about +Y; 0 = on +Z
    float phiDegrees = 90.0f;    // polar angle from +Y; 90 = horizontal
    float radius = 5.0f;         // metres
    float fovYDegrees = 45.0f;   // vertical field of view
    float znear = 0.0f;          // 0: radius / 1000

    // eye = target + radius · (sin φ sin θ, cos φ, sin φ cos θ)
    glm::vec3 eye() const;
    ViewSetup view(float aspect) const;

    // Looks at the centre of `bounds` from direction (θ, φ), far enough that the bounding sphere
    // fits the narrower of the two fields of view.
    static OrbitCamera framing(const Aabb& bounds, float aspect, float thetaDegrees = 0.0f, float phiDegrees = 90.0f,
                               float fovYDegrees = 45.0f);
};

// The view of a glTF camera; the viewport's aspect is used when the camera has none.
ViewSetup cameraView(const Camera& camera, float viewportAspect);

}  // namespace candela::scene
