#pragma once
// The cameras of a set of images as NeRF's transforms.json, which reconstruction and Gaussian-
// splatting tools (instant-ngp, nerfstudio, 3D Gaussian Splatting's loaders) read; docs/datasets.md.

#include "candela/image.h"
#include "candela/version.h"

#include <string>
#include <vector>

namespace candela {

// One image of a dataset.
struct DatasetFrame {
    std::string file;                         // its path, relative to the transforms file's folder
    CameraInfo camera;                        // Image::camera
    float environmentRotationDegrees = 0.0f;  // the lighting it had (RenderOptions, jittered)
};

// The JSON of `frames` (at least one) in the transforms.json convention: the intrinsics shared by
// every frame at the top (w, h, fl_x, fl_y, cx, cy in pixels, camera_angle_x and _y in radians),
// or per frame where they differ; per frame file_path and transform_matrix (camera to world, rows
// of 4, glTF's axes: the camera looks down −Z with +Y up, as NeRF's OpenGL convention; the world
// +Y up, metres). Candela's own fields: near and far planes (far null: none) and each frame's
// environment rotation. Throws InputError for no frames or an orthographic camera (the convention
// has no orthographic cameras).
CANDELA_API std::string transformsJson(const std::vector<DatasetFrame>& frames);

}  // namespace candela
