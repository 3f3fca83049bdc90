#pragma once
// Cameras: the orbit camera of the original project (target, angles, distance), glTF cameras, and
// reverse-Z projections with an infinite far plane (depth 1 at the near plane → 0 at infinity), so
// scenes from millimetres to kilometres keep depth precision. Vulkan clip space: y down, z in [0,1].

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <string>

namespace candela::scene {

// The orbit camera's default direction: the front (+Z, θ = 0) from 15° above the horizon (φ = 75°),
// as model-viewer's default camera-orbit "0deg 75deg"; a flat model lying in the ground plane is
// then seen, not edge-on (docs/scenes.md, "Framing").
constexpr float kDefaultOrbitPolarDegrees = 75.0f;
// The cone framing fits the bounding sphere in (scene/framing.h), and the field of view of an orbit
// camera given a distance without one.
constexpr float kFramingFovYDegrees = 45.0f;

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
// Whether a reverse-Z `projection` puts the far plane at infinity (perspectiveReverseZ without zfar,
// and the intrinsics' projection): depth then never reaches the cleared 0 on geometry, which a
// finite far plane's depth does at the plane.
inline bool farPlaneAtInfinity(const glm::mat4& projection) { return projection[2][2] == 0.0f; }

// A pinhole camera's intrinsics as fractions of the image: focal lengths fx, cx in widths and fy,
// cy in heights. In pixels (multiplied by width, height) they are OpenCV's K = [fx 0 cx; 0 fy cy;
// 0 0 1] for an image whose top-left corner is (0, 0), v down, pixel (i, j) centred at (i + ½, j + ½):
// a point at (x, y, z) in the camera's glTF axes (looking down −Z, +Y up) lands at
// u = fx·x/(−z) + cx, v = fy·(−y)/(−z) + cy.
struct Intrinsics {
    float fx = 0.0f, fy = 0.0f, cx = 0.5f, cy = 0.5f;
};
// Perspective, reverse-Z, infinite far plane, with `k`'s focal lengths and principal point.
glm::mat4 perspectiveReverseZ(const Intrinsics& k, float znear);
// The intrinsics of a perspective `projection` (one of the above; the inverse of the line above).
Intrinsics intrinsicsOf(const glm::mat4& projection);

struct OrbitCamera {
    glm::vec3 target{0.0f};
    float thetaDegrees = 0.0f;   // azimuth about +Y; 0 = on +Z
    float phiDegrees = kDefaultOrbitPolarDegrees;  // polar angle from +Y; 90 = horizontal
    float radius = 5.0f;         // metres
    float fovYDegrees = 45.0f;   // vertical field of view
    float znear = 0.0f;          // 0: radius / 1000

    // eye = target + radius · (sin φ sin θ, cos φ, sin φ cos θ)
    glm::vec3 eye() const;
    ViewSetup view(float aspect) const;
};

// The direction (θ°, φ°) the orbit camera frames `scene` from when the command line gives none:
// Scene::framingAngles when the scene has its own (the built-in sphere grid: head-on), else the
// front from 15° above the horizon — from +X (θ = 90°) when the bounds are flat in X and not in Z,
// so that a plane facing ±X is not seen edge-on.
glm::vec2 defaultOrbitAngles(const Scene& scene);

// The command-line flags that reproduce `camera`: "--camera-orbit θ,φ,r --target x,y,z --fov f",
// each number in the shortest form that reads back as the same float (the same image).
std::string orbitCameraFlags(const OrbitCamera& camera);

// The view of a glTF camera; the viewport's aspect is used when the camera has none.
ViewSetup cameraView(const Camera& camera, float viewportAspect);

// The view of a camera placed by its camera-to-world matrix (rotation and translation; glTF's axes)
// with a vertical field of view (radians) at `aspect`; its near plane 1/1000 of the distance from
// the eye to the centre of `bounds` (at least 1e-4 of the box's diagonal; 0.01 for invalid bounds),
// as the orbit camera's is 1/1000 of its distance to its target.
ViewSetup placedView(const glm::mat4& cameraToWorld, float fovY, float aspect, const Aabb& bounds);

}  // namespace candela::scene
