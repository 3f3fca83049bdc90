#pragma once
// HDR environments for image-based lighting: equirectangular linear-RGB maps loaded from Radiance
// .hdr or OpenEXR files (or built by makeProceduralSky, procedural_sky.h). CPU only, no Vulkan.
//
// Orientation: a world direction d samples u = 0.5 + atan2(d.z, d.x)/2π, v = acos(d.y)/π, v = 0
// being the top row (the Khronos glTF Sample Viewer's convention); the functions and the meaning
// of the environment rotation are in shaders/shared/environment.h. Formats, header tolerance and
// sanitizing: docs/environments.md.
//
//     assets::Environment env = assets::loadEnvironment("venice_sunset_1k.hdr");
//     for (const std::string& w : env.report.warnings) log::warn(w);
//     const float* texel = env.texel(x, y);  // linear R, G, B

#include "core/load_report.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <span>
#include <vector>

namespace candela::assets {

// An equirectangular environment map. Texels are finite and ≥ 0 (loadEnvironment and
// makeProceduralSky guarantee it; see sanitizeEnvironment).
struct Environment {
    std::string source;                  // the file's path, or "procedural sky"
    uint32_t width = 0;                  // texels per row (360° of azimuth)
    uint32_t height = 0;                 // rows (180° of elevation, top row = +Y)
    std::vector<float> rgb;              // linear RGB, width × height × 3 floats, top row first
    uint32_t replacedTexels = 0;         // texels that had a NaN, ±Inf or negative channel
    LoadReport report;                   // its lines begin "SOURCE: "

    size_t texelCount() const { return size_t(width) * height; }
    // The three floats of texel (x, y), y = 0 the top row. Preconditions: x < width, y < height.
    const float* texel(uint32_t x, uint32_t y) const { return rgb.data() + (size_t(y) * width + x) * 3; }
    float* texel(uint32_t x, uint32_t y) { return rgb.data() + (size_t(y) * width + x) * 3; }
};

struct EnvironmentLoadOptions {
    // Files declaring a larger width or height are rejected before any pixel memory is allocated
    // (16384 × 8192 × 3 floats = 1.5 GiB).
    uint32_t maxWidth = 16384;
    uint32_t maxHeight = 8192;
};

// Loads a Radiance RGBE (.hdr/.pic) or OpenEXR (.exr) equirectangular map, told apart by content
// (the extension only picks the format named in an error when the content matches neither).
// Throws candela::UserError with one line "PATH: problem" for anything unreadable or malformed
// (missing file, truncation at any byte, bad magic, unsupported format, absurd size, corrupt RLE);
// never reads out of bounds. NaN, Inf and negative texels are repaired by sanitizeEnvironment and
// reported in `warnings`, as are header values that are deliberately ignored (EXPOSURE=).
Environment loadEnvironment(const std::filesystem::path& path, const EnvironmentLoadOptions& options = {});
// As loadEnvironment, for a file's contents in memory: `source` names it in messages (and its
// extension the format named when the content matches neither). Borrows `bytes` for the call.
Environment decodeEnvironment(std::span<const uint8_t> bytes, const std::string& source,
                              const EnvironmentLoadOptions& options = {});

// Replaces non-finite and negative channel values in `env.rgb` and counts the texels touched into
// `env.replacedTexels` (added to any previous count); appends one warning line when any were found.
// NaN, −Inf and negative values become 0. +Inf becomes the largest finite value in the map, but at
// least 65504 (half-float maximum: an Inf in a half-float EXR means the value overflowed that).
// −0 becomes +0 (uncounted) so equal maps hash equally. Returns the number of texels replaced now.
uint32_t sanitizeEnvironment(Environment& env);

// Throws UserError "SOURCE: ..." when width or height is 0 or beyond the options' limits. The
// readers call it before allocating pixel memory.
void checkEnvironmentSize(const std::string& source, uint64_t width, uint64_t height,
                          const EnvironmentLoadOptions& options);

// wordHash64 (core/cache_files.h) of the width, height and texel bits as little-endian 32-bit
// words (the source and warnings are not hashed): the key of the on-disk IBL cache. Equal maps give
// equal hashes on every platform.
uint64_t contentHash(const Environment& env);

}  // namespace candela::assets
