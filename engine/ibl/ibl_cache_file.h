#pragma once
// The on-disk cache of precomputed image-based-lighting maps (prefiltered specular cube,
// irradiance SH or cube, split-sum BRDF LUT): the renderer reads its GPU results back, stores them
// under a key made of the environment's content hash and the quality settings, and loads them on
// the next run instead of recomputing. Pure C++, no Vulkan calls. A file that fails to read for
// any reason is a cache miss: the caller recomputes and overwrites it.
//
//     const IblCacheKey key{assets::contentHash(env), settingsText};
//     const std::filesystem::path file = cacheFilePath(cacheDir, key);
//     std::string why;
//     if (auto images = readCacheFile(file, key, &why)) { /* upload *images */ }
//     else { log::info(why); /* compute, read back */ writeCacheFile(file, key, computed); }
//
// File layout, all integers little-endian, no padding:
//     magic           12 bytes  "CANDELA-IBL\0"
//     version         u32       kIblCacheVersion (2)
//     environmentHash u64       IblCacheKey::environmentHash
//     settingsLength  u32       then that many bytes: IblCacheKey::settings (no terminator)
//     imageCount      u32       ≤ kIblCacheMaxImages, then per image:
//         nameLength  u32       1..kIblCacheMaxNameLength, then the name's bytes
//         format      u32       CachedImage::format (opaque here: a VkFormat value)
//         texelBytes  u32       1..16
//         width       u32       1..kIblCacheMaxExtent
//         height      u32       1..kIblCacheMaxExtent
//         layers      u32       1..kIblCacheMaxLayers
//         mips        u32       1..kIblCacheMaxMips and ≤ 1 + floor(log2(max(width, height)))
//         dataBytes   u64       == CachedImage::expectedBytes(), then the texels (CachedImage::data)
//     checksum        u64       wordHash64(0, every byte before it) (core/cache_files.h)
// The images' dataBytes sum to at most kIblCacheMaxPayloadBytes.

#include "core/cache_files.h"  // fnv1a64: the settings part of file names; wordHash64: the checksum

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace candela::ibl {

// 2: the checksum is wordHash64, not FNV-1a (a quarter of the time to read a file).
inline constexpr uint32_t kIblCacheVersion = 2;
inline constexpr uint32_t kIblCacheMaxImages = 16;
inline constexpr uint32_t kIblCacheMaxNameLength = 64;
inline constexpr uint32_t kIblCacheMaxExtent = 16384;   // width and height
inline constexpr uint32_t kIblCacheMaxLayers = 64;
inline constexpr uint32_t kIblCacheMaxMips = 16;
inline constexpr uint32_t kIblCacheMaxTexelBytes = 16;
inline constexpr uint64_t kIblCacheMaxPayloadBytes = uint64_t(2) << 30;  // 2 GiB, all images together

// One image's texels, tightly packed.
struct CachedImage {
    std::string name;             // e.g. "specular", "irradiance_sh", "brdf_lut"
    uint32_t format = 0;          // the VkFormat value (opaque to this file)
    uint32_t texelBytes = 0;      // bytes per texel (1..16)
    uint32_t width = 0, height = 0, layers = 0, mips = 0;
    std::vector<std::byte> data;  // mip-major: for mip m (max(1, width >> m) × max(1, height >> m)),
                                  // all layers in order, each layer's rows top first

    // The byte size `data` must have: the sum over mips of mip width × height × layers × texelBytes.
    // Any dimensions are accepted; returns SIZE_MAX if the size does not fit in size_t.
    size_t expectedBytes() const;
};

// What a cache file was made for. Both parts must match for a file to be used.
struct IblCacheKey {
    uint64_t environmentHash = 0;  // assets::contentHash of the environment
    // Canonical text of everything else that changes the maps: the quality settings and the hash of
    // the precompute shaders' SPIR-V, e.g. "v4 cube=256 ... shaders=0123456789abcdef".
    std::string settings;
};

// At most this much of a cache folder's .cibl files is kept (evictCacheFiles).
inline constexpr uint64_t kIblCacheCapBytes = uint64_t(1) << 30;  // 1 GiB

// dir / "<16 lowercase hex digits of environmentHash>-<16 of fnv1a64(settings)>.cibl". Two keys
// may share a name (a hash collision); readCacheFile compares the full key, so a collision is only
// a cache miss.
std::filesystem::path cacheFilePath(const std::filesystem::path& dir, const IblCacheKey& key);

// Writes `images` under `key` to `path` atomically: into a uniquely named temporary file in the
// same directory ("<file name>.tmp-<hex>"), then renamed over `path`, so readers see either the
// old file or the complete new one (a crash may leave a stale temporary; an unsynced rename after
// a power loss may leave a file that fails its checksum, i.e. a cache miss). Creates the parent
// directory if needed. The temporary is removed on failure.
// Preconditions: at most kIblCacheMaxImages images, each within the layout's limits above with
// data.size() == expectedBytes(); otherwise throws std::invalid_argument (nothing is written).
// Throws candela::UserError "PATH: problem" (one line, PATH = `path`) on I/O failure: the
// directory cannot be created, the file cannot be written (disk full), the rename fails.
void writeCacheFile(const std::filesystem::path& path, const IblCacheKey& key, const std::vector<CachedImage>& images);

// Reads and fully validates the cache file at `path`. Returns its images, in the order written,
// or nullopt with one line "PATH: problem" in *reason (when `reason` is not null) if the file is
// missing or unreadable, has a bad magic or another version, was made for another key (hash or
// settings: the full settings string is compared), is truncated at any byte, has bytes after the
// checksum, declares dimensions beyond the layout's limits or a data size disagreeing with them,
// or fails its checksum. Every declared size is checked against the limits and the bytes left in
// the file before anything is allocated: the images' data never exceeds the file's size. Never
// throws for bad content (only std::bad_alloc could escape); never reads out of bounds.
std::optional<std::vector<CachedImage>> readCacheFile(const std::filesystem::path& path, const IblCacheKey& key,
                                                      std::string* reason);

}  // namespace candela::ibl
