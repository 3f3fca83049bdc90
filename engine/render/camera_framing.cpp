#include "render/camera_framing.h"

#include "pose/shown_points.h"
#include "scene/framing.h"

#include <cstdio>
#include <string>
#include <vector>

namespace candela {
namespace {

std::string seconds(double t) {
    char text[32];
    std::snprintf(text, sizeof text, "%g s", t);
    return text;
}

// What framing fitted and how, for --explain (CameraSettings::framing).
std::string framingNote(bool posed, std::span<const double> times, size_t directions, bool distance, bool fov) {
    std::string out = !posed ? "the scene's vertices"
                      : times.size() == 1 ? "the vertices of the pose at " + seconds(times[0])
                                          : "the vertices of the poses at " + std::to_string(times.size()) + " times (" +
                                                seconds(times.front()) + " to " + seconds(times.back()) + ")";
    if (directions > 1) out += ", seen from " + std::to_string(directions) + " directions";
    out += ": the target at the centre of their box";
    if (!distance) out += ", the distance R / sin 15° (R: the farthest vertex from it)";
    if (!distance && !fov) out += ", the field of view fitted to leave 10% of the image around the silhouette";
    return out;
}

}  // namespace

CameraSettings resolveFraming(const scene::Scene& scene, const CameraSettings& camera, float aspect, const pose::ScenePose* pose,
                              std::span<const double> times, std::span<const glm::vec2> given, bool loop) {
    CameraSettings out = camera;
    if (camera.orbitCamera) return out;
    const glm::vec2 own(camera.orbit.value_or(glm::vec3(scene::defaultOrbitAngles(scene), 0.0f)));
    const std::span<const glm::vec2> directions = given.empty() ? std::span(&own, 1) : given;
    const bool distance = camera.orbit && camera.orbit->z > 0.0f;
    if (distance && camera.target) {
        out.orbit = glm::vec3(directions[0], camera.orbit->z);
        out.fovYDegrees = camera.fovYDegrees.value_or(scene::kFramingFovYDegrees);
        return out;
    }
    const bool posed = pose && pose->movesNodes();
    std::vector<double> at(times.begin(), times.end());
    if (at.empty() && posed) at.push_back(pose->time());
    const std::optional<float> fov = distance ? camera.fovYDegrees.value_or(scene::kFramingFovYDegrees) : camera.fovYDegrees;
    const std::string note = framingNote(posed, at, directions.size(), distance, camera.fovYDegrees.has_value());
    const scene::OrbitCamera framed =
        scene::frame(pose::shownPoints(scene, pose, std::move(at), loop),
                     {.aspect = aspect, .directions = {directions.begin(), directions.end()}, .fovYDegrees = fov});
    out.orbit = glm::vec3(directions[0], distance ? camera.orbit->z : framed.radius);
    out.target = camera.target.value_or(framed.target);
    out.fovYDegrees = framed.fovYDegrees;
    out.framing = note;
    return out;
}

}  // namespace candela
