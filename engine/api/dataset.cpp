// candela::transformsJson (candela/dataset.h): the cameras of a set of images as NeRF's
// transforms.json.

#include "api/access.h"
#include "candela/dataset.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace candela {
namespace {

using Json = nlohmann::ordered_json;

// The intrinsics the convention names, of one camera.
Json intrinsicsOf(const CameraInfo& c) {
    Json out;
    out["w"] = c.width;
    out["h"] = c.height;
    out["fl_x"] = c.intrinsics[0];
    out["fl_y"] = c.intrinsics[1];
    out["cx"] = c.intrinsics[2];
    out["cy"] = c.intrinsics[3];
    out["camera_angle_x"] = 2.0 * std::atan(0.5 * c.width / c.intrinsics[0]);
    out["camera_angle_y"] = 2.0 * std::atan(0.5 * c.height / c.intrinsics[1]);
    return out;
}

Json planesOf(const CameraInfo& c) {
    return {{"near", c.znear}, {"far", std::isinf(c.zfar) ? Json(nullptr) : Json(c.zfar)}};
}

}  // namespace

std::string transformsJson(const std::vector<DatasetFrame>& frames) {
    std::string text;
    translateErrors("", [&] {
        if (frames.empty()) throw UserError("transforms.json: no frames");
        for (const DatasetFrame& frame : frames)
            if (frame.camera.orthographic)
                throw UserError("transforms.json: " + frame.file + " was rendered with an orthographic camera, which the convention cannot hold");
        const Json shared = intrinsicsOf(frames.front().camera);
        const Json sharedPlanes = planesOf(frames.front().camera);
        bool same = true, samePlanes = true;
        for (const DatasetFrame& frame : frames) {
            same = same && intrinsicsOf(frame.camera) == shared;
            samePlanes = samePlanes && planesOf(frame.camera) == sharedPlanes;
        }
        Json out = same ? shared : Json::object();
        out["candela"] = {{"axes", "glTF: world +Y up, metres; camera looks down -Z, +Y up (OpenGL, as NeRF)"},
                          {"pixel_centers", "(i + 0.5, j + 0.5), v down"}};
        if (samePlanes) out["candela"].update(sharedPlanes);
        Json list = Json::array();
        for (const DatasetFrame& frame : frames) {
            Json entry;
            entry["file_path"] = frame.file;
            Json matrix = Json::array();
            for (int r = 0; r < 4; ++r)
                matrix.push_back({frame.camera.cameraToWorld[r], frame.camera.cameraToWorld[4 + r],
                                  frame.camera.cameraToWorld[8 + r], frame.camera.cameraToWorld[12 + r]});
            entry["transform_matrix"] = matrix;
            if (!same) entry.update(intrinsicsOf(frame.camera));
            if (!samePlanes) entry.update(planesOf(frame.camera));
            entry["environment_rotation_degrees"] = frame.environmentRotationDegrees;
            list.push_back(entry);
        }
        out["frames"] = list;
        text = out.dump(2) + "\n";
    });
    return text;
}

}  // namespace candela
