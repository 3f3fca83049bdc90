// The public cameras and sequences (candela/render.h, device.h): the renderer's camera settings of a
// Camera, the CameraInfo of a view, the frames of turntables and views with their lighting, lookAt,
// and the view directions.

#include "api/access.h"
#include "api/cameras.h"
#include "render/camera_framing.h"
#include "render/renderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>

namespace candela {
namespace {

glm::vec3 vec3Of(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

// The further turn of frame i's environment with jittered lighting: 360° × a uniform number from
// (seed, i) by SplitMix64, the same on every machine.
float lightingJitterDegrees(uint64_t seed, uint32_t i) {
    uint64_t z = seed + (uint64_t(i) + 1) * 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return float(double(z >> 11) * 0x1.0p-53 * 360.0);
}

}  // namespace

CameraSettings cameraSettings(const RenderOptions& options) {
    const Camera& camera = options.camera;
    CameraSettings out;
    out.gltfCamera = camera.gltfCamera;
    if (camera.orbit) out.orbit = vec3Of(*camera.orbit);
    if (camera.target) out.target = vec3Of(*camera.target);
    out.fovYDegrees = camera.fovYDegrees;
    if (camera.cameraToWorld) {
        glm::mat4 m;
        std::memcpy(&m[0][0], camera.cameraToWorld->data(), sizeof(m));
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(m[c][r])) throw UserError("Camera::cameraToWorld: a value is not finite");
        if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)
            throw UserError("Camera::cameraToWorld: the last row is not 0 0 0 1");
        if (std::abs(glm::determinant(glm::mat3(m))) < 1e-12f) throw UserError("Camera::cameraToWorld: the matrix is singular");
        out.cameraToWorld = m;
    }
    if (camera.intrinsics) {
        const auto& k = *camera.intrinsics;
        for (float value : k)
            if (!std::isfinite(value)) throw UserError("Camera::intrinsics: a value is not finite");
        if (!(k[0] > 0.0f && k[1] > 0.0f)) throw UserError("Camera::intrinsics: the focal lengths fx and fy must be positive");
        const float width = float(std::max(options.width, 1u)), height = float(std::max(options.height, 1u));
        out.intrinsics = scene::Intrinsics{.fx = k[0] / width, .fy = k[1] / height, .cx = k[2] / width, .cy = k[3] / height};
    }
    return out;
}

CameraInfo cameraInfo(const scene::ViewSetup& view, uint32_t width, uint32_t height) {
    CameraInfo info{.width = width, .height = height};
    const glm::mat4 cameraToWorld = glm::inverse(view.view);
    std::memcpy(info.cameraToWorld.data(), &cameraToWorld[0][0], sizeof(cameraToWorld));
    std::memcpy(info.projection.data(), &view.projection[0][0], sizeof(view.projection));
    const glm::mat4& p = view.projection;
    info.orthographic = p[2][3] == 0.0f;  // w does not depend on depth
    if (info.orthographic) {
        info.xmag = 1.0f / p[0][0];
        info.ymag = -1.0f / p[1][1];
        info.zfar = p[3][2] / p[2][2];
        info.znear = info.zfar - 1.0f / p[2][2];
        return info;
    }
    const scene::Intrinsics k = scene::intrinsicsOf(p);
    info.intrinsics = {k.fx * float(width), k.fy * float(height), k.cx * float(width), k.cy * float(height)};
    info.fovYDegrees = glm::degrees(2.0f * std::atan(0.5f / k.fy));
    info.znear = view.znear;
    if (p[2][2] != 0.0f) info.zfar = p[3][2] / p[2][2];
    return info;
}

SequenceCamera sequenceCamera(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                              const pose::ScenePose& pose, const RenderOptions& options, const SequenceOptions& sequence) {
    SequenceCamera out{.camera = camera};
    const bool turntable = sequence.views.empty() && sequence.frames > 1 && sequence.turntableDegrees != 0.0f;
    if (camera.gltfCamera || camera.cameraToWorld || camera.orbitCamera) {
        if (!sequence.views.empty()) throw UserError("views of a scene need the orbit camera, not a glTF or placed camera");
        return out;  // (a turntable of a fixed camera does not turn)
    }
    const glm::vec3 base = camera.orbit.value_or(glm::vec3(scene::defaultOrbitAngles(scene), 0.0f));
    const uint32_t frames = frameCount(sequence);
    std::vector<glm::vec2> directions;
    for (uint32_t i = 0; i < ((turntable || !sequence.views.empty()) ? frames : 1u); ++i)
        directions.push_back(turntable ? glm::vec2(base.x + sequence.turntableDegrees * float(i) / float(sequence.frames), base.y)
                             : sequence.views.empty() ? glm::vec2(base)
                                                      : glm::vec2(sequence.views[i][0], sequence.views[i][1]));
    std::vector<double> times;
    for (uint32_t i = 0; i < (sequence.views.empty() ? frames : 1u); ++i) times.push_back(frameTime(options, sequence, i));
    out.camera = resolveFraming(scene, camera, aspect, &pose, times, directions);
    if (directions.size() > 1 || turntable)
        for (const glm::vec2& direction : directions) out.orbits.push_back(glm::vec3(direction, out.camera.orbit->z));
    return out;
}

void checkSequence(const SequenceOptions& sequence) {
    if (!sequence.views.empty()) {
        for (const auto& view : sequence.views)
            if (!std::isfinite(view[0]) || !std::isfinite(view[1])) throw UserError("a view direction is not finite");
        return;
    }
    if (sequence.frames == 0) throw UserError("an image sequence of 0 frames");
    if (!(sequence.fps > 0.0)) throw UserError("an image sequence at " + std::to_string(sequence.fps) + " frames per second");
}

double frameTime(const RenderOptions& options, const SequenceOptions& sequence, uint32_t i) {
    return sequence.views.empty() ? options.time + double(i) / sequence.fps : options.time;
}

float frameEnvironmentRotation(const RenderOptions& options, const SequenceOptions& sequence, uint32_t i) {
    return options.environmentRotationDegrees + (sequence.lightingSeed ? lightingJitterDegrees(*sequence.lightingSeed, i) : 0.0f);
}

RenderOptions sequenceFrame(const Scene& scene, const RenderOptions& options, const SequenceOptions& sequence,
                            uint32_t index) {
    const scene::Scene& held = Access::impl(scene).scene;
    RenderOptions out = options;
    translateErrors(held.source, [&] {
        checkSequence(sequence);
        if (index >= frameCount(sequence))
            throw UserError("frame " + std::to_string(index) + " of a sequence of " + std::to_string(frameCount(sequence)));
        if (options.width == 0 || options.height == 0) throw UserError("an image of " + std::to_string(options.width) + "x" + std::to_string(options.height) + " pixels");
        pose::ScenePose pose(held, pose::selectAnimations(held, options.animations));
        pose.evaluate(options.time);
        const float aspect = float(options.width) / float(options.height);
        out.time = frameTime(options, sequence, index);
        out.environmentRotationDegrees = frameEnvironmentRotation(options, sequence, index);
        const SequenceCamera framed = sequenceCamera(held, cameraSettings(options), aspect, pose, options, sequence);
        const glm::vec3 orbit = framed.orbits.empty() ? framed.camera.orbit.value_or(glm::vec3(0.0f)) : framed.orbits[index];
        if (framed.camera.orbit) out.camera.orbit = std::array<float, 3>{orbit.x, orbit.y, orbit.z};
        if (framed.camera.target) out.camera.target = std::array<float, 3>{framed.camera.target->x, framed.camera.target->y, framed.camera.target->z};
        out.camera.fovYDegrees = framed.camera.fovYDegrees;
    });
    return out;
}

std::vector<std::array<float, 2>> sphereViews(uint32_t count) {
    std::vector<std::array<float, 2>> views;
    const double golden = 180.0 * (3.0 - std::sqrt(5.0));  // 137.5°
    for (uint32_t i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / count;  // cos φ at equal steps
        views.push_back({float(std::fmod(golden * i, 360.0)), float(glm::degrees(std::acos(y)))});
    }
    return views;
}

std::vector<std::array<float, 2>> ringViews(uint32_t count, float elevationDegrees) {
    std::vector<std::array<float, 2>> views;
    for (uint32_t i = 0; i < count; ++i) views.push_back({360.0f * float(i) / float(count), 90.0f - elevationDegrees});
    return views;
}

Camera lookAt(const std::array<float, 3>& eye, const std::array<float, 3>& target, const std::array<float, 3>& up) {
    Camera camera;
    translateErrors("", [&] {
        const glm::vec3 from = vec3Of(eye), to = vec3Of(target), upward = vec3Of(up);
        const float distance = glm::length(to - from);
        if (!std::isfinite(distance) || !(distance > 0.0f)) throw UserError("lookAt: the eye and the target are one point");
        if (glm::length(glm::cross((to - from) / distance, upward)) < 1e-6f * glm::length(upward) || glm::length(upward) == 0.0f)
            throw UserError("lookAt: the up vector is parallel to the line of sight");
        const glm::mat4 cameraToWorld = glm::inverse(glm::lookAt(from, to, upward));
        camera.cameraToWorld.emplace();
        std::memcpy(camera.cameraToWorld->data(), &cameraToWorld[0][0], sizeof(cameraToWorld));
    });
    return camera;
}

}  // namespace candela
