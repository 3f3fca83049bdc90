#pragma once
// Images in host memory, as Device::render returns them, and writing them to files.

#include "candela/version.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace candela {

enum class PixelFormat {
    Rgba8Srgb,    // 4 bytes a pixel: tone-mapped, sRGB-encoded, alpha = coverage (a PNG's pixels)
    Rgba16Float,  // 8 bytes: linear scene-referred light before tone mapping (IEEE half floats)
    Rgba32Float,  // 16 bytes: the same as 32-bit floats
};

// Bytes per pixel of `format`.
CANDELA_API std::size_t bytesPerPixel(PixelFormat format) noexcept;

// The camera an image was rendered with (docs/datasets.md, "Cameras").
struct CameraInfo {
    uint32_t width = 0, height = 0;  // the image's size in pixels
    // Camera to world, column-major (element [4·c + r] is row r of column c), in glTF's axes: the
    // camera looks down its −Z, +X right and +Y up in the image; metres.
    std::array<float, 16> cameraToWorld{};
    bool orthographic = false;  // a glTF orthographic camera: no intrinsics; see xmag, ymag
    // Perspective cameras: fx, fy, cx, cy in pixels, OpenCV's K = [fx 0 cx; 0 fy cy; 0 0 1] for an
    // image whose top-left corner is (0, 0), v down and pixel (i, j) centred at (i + ½, j + ½): a
    // point at (x, y, z) in the camera's axes lands at u = fx·x/(−z) + cx, v = −fy·y/(−z) + cy.
    std::array<float, 4> intrinsics{};
    float fovYDegrees = 0.0f;  // vertical field of view (perspective)
    float xmag = 0.0f, ymag = 0.0f;  // half width and height of an orthographic view (metres)
    float znear = 0.0f;  // near plane (metres)
    float zfar = std::numeric_limits<float>::infinity();  // far plane (infinity: none)
    // The projection the image was drawn with: Vulkan clip space (y down), reverse Z (depth 1 at
    // znear, 0 at zfar or infinity), column-major.
    std::array<float, 16> projection{};
};

// An image in host memory: rows top first, each width × bytesPerPixel(format) bytes, no padding.
struct Image {
    uint32_t width = 0;
    uint32_t height = 0;
    PixelFormat format = PixelFormat::Rgba8Srgb;
    std::vector<std::byte> pixels;
    CameraInfo camera;  // the camera it was rendered with (Device::render, renderSequence)
};

// Writes `image` to `path` as `candela render --out` does: .png from Rgba8Srgb; .exr (half-float
// RGBA) or .pfm (float RGB) from either float format. Throws InputError naming the file for another
// extension, a pixel format the file type does not hold, or a file that cannot be written.
CANDELA_API void writeImage(const std::string& path, const Image& image);

}  // namespace candela
