#pragma once
// The on-disk cache of levels of detail: for one scene's candidate meshes (geometry/mesh_optimize.h
// lodCandidates), either their chains, built by an earlier run, or — until a run builds them — how
// many frames earlier runs drew them at full detail, so that the rent-or-buy choice of
// geometry/lod_cost.h counts the frames of every run (geometry/lod_cache.h decides). Pure C++. A
// file that fails to read for any reason is a cache miss: the caller decides anew and overwrites it.
//
// File layout, all integers little-endian, no padding:
//     magic          12 bytes  "CANDELA-LOD\0"
//     version        u32       kLodCacheVersion (2)
//     contentHash    u64       LodCacheKey::contentHash
//     settingsLength u32       ≤ kLodCacheMaxSettingsLength, then that many bytes: LodCacheKey::settings
//     framesDrawn    u64       LodCacheRecord::framesDrawn
//     meshCount      u32       0 without chains; else the candidates' count, then per mesh:
//         levelCount u32       ≤ kLodCacheMaxLevels (0: the mesh does not simplify), then per level:
//             error  f32       finite, ≥ 0, not below the previous level's
//             count  u32       indices: a positive multiple of 3, fewer than the mesh's (and the previous level's)
//             indices u32 × count, each < the mesh's vertex count
//     checksum       u64       wordHash64(0, every byte before it) (core/cache_files.h)

#include "geometry/mesh_lod.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace candela::geometry {

// 2: the checksum is wordHash64, not FNV-1a.
inline constexpr uint32_t kLodCacheVersion = 2;
inline constexpr uint32_t kLodCacheMaxLevels = 16;
inline constexpr uint32_t kLodCacheMaxSettingsLength = 4096;
// At most this much of a cache folder's .clod files is kept (evictCacheFiles).
inline constexpr uint64_t kLodCacheCapBytes = uint64_t(1) << 30;  // 1 GiB

// What a cache file was made for. Both parts must match for a file to be used.
struct LodCacheKey {
    uint64_t contentHash = 0;  // of the candidates' positions and indices (geometry/lod_cache.h)
    std::string settings;      // canonical text of the simplifier's settings and version
};

// What the reader checks a file's chains against: one candidate mesh.
struct LodCacheMesh {
    uint32_t vertexCount = 0;
    uint32_t indexCount = 0;
};

struct LodCacheRecord {
    // Frames drawn at full detail by the runs that did not build the chains.
    uint64_t framesDrawn = 0;
    // Per candidate mesh, its levels beyond the full detail (empty: it does not simplify), indices
    // relative to the mesh's first vertex; nullopt until a run builds them.
    std::optional<std::vector<std::vector<SimplifiedLevel>>> chains;
};

// dir / "<16 hex digits of contentHash>-<16 of fnv1a64(settings)>.clod". Two keys may share a name
// (a hash collision); the reader compares the full key, so a collision is only a cache miss.
std::filesystem::path lodCacheFilePath(const std::filesystem::path& dir, const LodCacheKey& key);

// The file's bytes for `record` under `key`. Precondition: the chains, when present, keep the
// layout's limits (simplifyCandidates' do); otherwise throws std::invalid_argument.
std::vector<std::byte> encodeLodCache(const LodCacheKey& key, const LodCacheRecord& record);

// Writes encodeLodCache's bytes to `path` atomically (core/cache_files.h writeFileAtomically).
// Throws candela::UserError "PATH: problem" on I/O failure.
void writeLodCacheFile(const std::filesystem::path& path, const LodCacheKey& key, const LodCacheRecord& record);

// Parses and fully validates a cache file's bytes against `key` and the candidate `meshes`.
// Returns the record, or nullopt with one line "problem" in *reason (when not null) for a bad magic
// or another version, another key (hash or settings, compared in full), a truncation at any byte,
// bytes after the checksum, chains for another number of meshes, a level beyond the limits above
// or an index beyond its mesh's vertices, or a checksum mismatch. Every count is checked against
// the bytes left before anything is allocated. Never throws for bad content; never reads out of
// bounds.
std::optional<LodCacheRecord> parseLodCache(std::span<const std::byte> bytes, const LodCacheKey& key,
                                            std::span<const LodCacheMesh> meshes, std::string* reason);

// Reads the file at `path` and parses it (parseLodCache); a missing or unreadable file is a miss
// too. *reason then reads "PATH: problem".
std::optional<LodCacheRecord> readLodCacheFile(const std::filesystem::path& path, const LodCacheKey& key,
                                               std::span<const LodCacheMesh> meshes, std::string* reason);

}  // namespace candela::geometry
