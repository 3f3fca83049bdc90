#pragma once
// Images in host memory, as Device::render returns them, and writing them to files.

#include "candela/version.h"

#include <cstddef>
#include <cstdint>
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

// An image in host memory: rows top first, each width × bytesPerPixel(format) bytes, no padding.
struct Image {
    uint32_t width = 0;
    uint32_t height = 0;
    PixelFormat format = PixelFormat::Rgba8Srgb;
    std::vector<std::byte> pixels;
};

// Writes `image` to `path` as `candela render --out` does: .png from Rgba8Srgb; .exr (half-float
// RGBA) or .pfm (float RGB) from either float format. Throws InputError naming the file for another
// extension, a pixel format the file type does not hold, or a file that cannot be written.
CANDELA_API void writeImage(const std::string& path, const Image& image);

}  // namespace candela
