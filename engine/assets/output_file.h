#pragma once
// Writing per-pixel outputs besides colour (docs/outputs.md): one multi-channel OpenEXR file
// (32-bit float and uint channels, named, with the colour image's half R, G, B, A when given) or
// one NumPy .npy array per output. Written atomically (writeFileAtomically), as every image file;
// failures are UserErrors naming the file. What the outputs mean is the caller's (options/
// pixel_output.h, candela/image.h): here they are named planes of values.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace candela::assets {

// One output: width × height × channels values, rows top first, floats or (integer) uint32s.
struct OutputPlane {
    std::string name;                   // "depth", "normal", …
    std::vector<std::string> channels;  // the EXR channel names, in order ("Z"; "normal.X", …)
    bool integer = false;
    std::span<const float> floats;      // !integer
    std::span<const uint32_t> ids;      // integer
};

// `rgba` (width × height × 4 floats, or empty: no colour) as half R, G, B, A and each plane's
// channels as FLOAT or UINT, ZIP-compressed.
void writeOutputsExr(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const float> rgba,
                     std::span<const OutputPlane> planes);
// `plane` as a NumPy array (format 1.0): '<f4' or '<u4', shape (height, width) for one channel,
// else (height, width, channels), C order.
void writeNpy(const std::filesystem::path& path, uint32_t width, uint32_t height, const OutputPlane& plane);

// Whether `bytes` is a whole .npy file: a valid header whose shape and type the data fills exactly.
bool npyComplete(std::span<const uint8_t> bytes);
// Whether the EXR at `path` decodes whole, every channel of every scan line.
bool exrDecodesWhole(const std::filesystem::path& path);

}  // namespace candela::assets
