#include "scene/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace candela::scene {

glm::mat4 perspectiveReverseZ(float fovY, float aspect, float znear) {
    const float f = 1.0f / std::tan(fovY * 0.5f);
    glm::mat4 m(0.0f);
    m[0][0] = f / aspect;
    m[1][1] = -f;  // Vulkan clip space has y down
    m[2][3] = -1.0f;  // w = −z_view
    m[3][2] = znear;  // z = znear → depth = znear / −z_view
    return m;
}

glm::mat4 perspectiveReverseZ(float fovY, float aspect, float znear, float zfar) {
    const float f = 1.0f / std::tan(fovY * 0.5f);
    glm::mat4 m(0.0f);
    m[0][0] = f / aspect;
    m[1][1] = -f;
    // depth(z = −znear) = 1, depth(z = −zfar) = 0
    m[2][2] = znear / (zfar - znear);
    m[2][3] = -1.0f;
    m[3][2] = znear * zfar / (zfar - znear);
    return m;
}

glm::mat4 orthographicReverseZ(float xmag, float ymag, float znear, float zfar) {
    glm::mat4 m(1.0f);
    m[0][0] = 1.0f / xmag;
    m[1][1] = -1.0f / ymag;
    // depth = (z + zfar) / (zfar − znear) for view-space z in [−zfar, −znear]
    m[2][2] = 1.0f / (zfar - znear);
    m[3][2] = zfar / (zfar - znear);
    return m;
}

glm::mat4 perspectiveReverseZ(const Intrinsics& k, float znear) {
    // NDC x = 2u − 1 for u in image widths: x_clip = 2fx·x + (2cx − 1)·(−z); y likewise, v down.
    glm::mat4 m(0.0f);
    m[0][0] = 2.0f * k.fx;
    m[1][1] = -2.0f * k.fy;
    m[2][0] = 1.0f - 2.0f * k.cx;
    m[2][1] = 1.0f - 2.0f * k.cy;
    m[2][3] = -1.0f;
    m[3][2] = znear;
    return m;
}

Intrinsics intrinsicsOf(const glm::mat4& projection) {
    return {.fx = 0.5f * projection[0][0],
            .fy = -0.5f * projection[1][1],
            .cx = 0.5f * (1.0f - projection[2][0]),
            .cy = 0.5f * (1.0f - projection[2][1])};
}

glm::vec3 OrbitCamera::eye() const {
    const float theta = glm::radians(thetaDegrees), phi = glm::radians(phiDegrees);
    return target + radius * glm::vec3(std::sin(phi) * std::sin(theta), std::cos(phi), std::sin(phi) * std::cos(theta));
}

ViewSetup OrbitCamera::view(float aspect) const {
    ViewSetup out;
    out.eye = eye();
    const glm::vec3 forward = glm::normalize(target - out.eye);
    // Looking straight up or down: any horizontal up vector will do.
    const glm::vec3 up = std::abs(forward.y) > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    out.view = glm::lookAt(out.eye, target, up);
    out.znear = znear > 0.0f ? znear : radius / 1000.0f;
    out.projection = perspectiveReverseZ(glm::radians(fovYDegrees), aspect, out.znear);
    out.viewProjection = out.projection * out.view;
    return out;
}

glm::vec2 defaultOrbitAngles(const Scene& scene) {
    if (scene.framingAngles) return *scene.framingAngles;
    const glm::vec3 extent = scene.bounds.valid() ? scene.bounds.max - scene.bounds.min : glm::vec3(0.0f);
    const float flat = 1e-3f * std::max({extent.x, extent.y, extent.z});
    const bool facingX = extent.x <= flat && extent.z > flat;
    return {facingX ? 90.0f : 0.0f, kDefaultOrbitPolarDegrees};
}

namespace {
// The shortest decimal form of `value` that reads back (strtof) as the same float.
std::string shortest(float value) {
    std::array<char, 32> text{};
    const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
    return std::string(text.data(), result.ptr);
}
}  // namespace

std::string orbitCameraFlags(const OrbitCamera& camera) {
    return "--camera-orbit " + shortest(camera.thetaDegrees) + "," + shortest(camera.phiDegrees) + "," +
           shortest(camera.radius) + " --target " + shortest(camera.target.x) + "," + shortest(camera.target.y) + "," +
           shortest(camera.target.z) + " --fov " + shortest(camera.fovYDegrees);
}

ViewSetup cameraView(const Camera& camera, float viewportAspect) {
    ViewSetup out;
    out.eye = glm::vec3(camera.world[3]);
    out.view = glm::inverse(camera.world);
    out.znear = camera.znear;
    const float aspect = camera.aspectRatio > 0.0f ? camera.aspectRatio : viewportAspect;
    if (camera.perspective)
        out.projection = camera.zfar > 0.0f ? perspectiveReverseZ(camera.yfov, aspect, camera.znear, camera.zfar)
                                            : perspectiveReverseZ(camera.yfov, aspect, camera.znear);
    else
        out.projection = orthographicReverseZ(camera.xmag, camera.ymag, camera.znear, camera.zfar > 0.0f ? camera.zfar : 1e4f);
    out.viewProjection = out.projection * out.view;
    return out;
}

ViewSetup placedView(const glm::mat4& cameraToWorld, float fovY, float aspect, const Aabb& bounds) {
    ViewSetup out;
    out.eye = glm::vec3(cameraToWorld[3]);
    out.view = glm::inverse(cameraToWorld);
    out.znear = 0.01f;
    if (bounds.valid()) {
        const float diagonal = glm::length(bounds.max - bounds.min);
        out.znear = std::max(1e-3f * glm::length(out.eye - 0.5f * (bounds.min + bounds.max)), std::max(1e-4f * diagonal, 1e-6f));
    }
    out.projection = perspectiveReverseZ(fovY, aspect, out.znear);
    out.viewProjection = out.projection * out.view;
    return out;
}

}  // namespace candela::scene
