#include "scene/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
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

OrbitCamera OrbitCamera::framing(const Aabb& bounds, float aspect, float thetaDegrees, float phiDegrees,
                                 float fovYDegrees) {
    OrbitCamera camera;
    camera.thetaDegrees = thetaDegrees;
    camera.phiDegrees = phiDegrees;
    camera.fovYDegrees = fovYDegrees;
    if (!bounds.valid()) return camera;
    camera.target = 0.5f * (bounds.min + bounds.max);
    const float sphere = std::max(0.5f * glm::length(bounds.max - bounds.min), 1e-6f);
    const float halfY = glm::radians(fovYDegrees) * 0.5f;
    const float halfX = std::atan(std::tan(halfY) * aspect);
    camera.radius = sphere / std::sin(std::min(halfX, halfY)) * 1.05f;
    camera.znear = camera.radius * 1e-3f;
    return camera;
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

}  // namespace candela::scene
