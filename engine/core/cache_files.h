#pragma once
// What Candela's on-disk caches share (the IBL maps: ibl/ibl_cache_file.h; compiled pipelines:
// vk/pipeline_cache_file.h): the user's cache folder, the FNV-1a hash their files are keyed and
// checksummed with, and writing a file atomically. No Vulkan.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>

namespace candela {

// The user's cache folder for Candela, following the XDG base directory specification:
// "$XDG_CACHE_HOME/candela" when XDG_CACHE_HOME is an absolute path, else "$HOME/.cache/candela"
// when HOME is set and not empty, else an empty path (no cache folder). Reads the environment;
// creates nothing.
std::filesystem::path userCacheFolder();
// The same from given values of XDG_CACHE_HOME and HOME (null: unset). Pure.
std::filesystem::path userCacheFolder(const char* xdgCacheHome, const char* home);
// The pipeline cache's folder a choice names (--pipeline-cache, DeviceOptions::pipelineCache):
// "off" none (an empty path), "" the user's cache folder, anything else that folder.
std::filesystem::path pipelineCacheFolder(const std::string& choice);
// The IBL maps cache's folder a choice names (--ibl-cache, DeviceOptions::iblCache): "off" none (an
// empty path), "" the user's cache folder's "ibl" folder (none without a user's cache folder),
// anything else that folder.
std::filesystem::path iblCacheFolder(const std::string& choice);

inline constexpr uint64_t kFnv1a64Basis = 0xcbf29ce484222325ull;
inline constexpr uint64_t kFnv1a64Prime = 0x100000001b3ull;

// FNV-1a 64 of `size` bytes at `bytes`, continuing from `hash` (kFnv1a64Basis to start).
constexpr uint64_t fnv1a64Update(uint64_t hash, const void* bytes, size_t size) {
    const auto* p = static_cast<const unsigned char*>(bytes);
    for (size_t i = 0; i < size; ++i) {
        hash ^= p[i];
        hash *= kFnv1a64Prime;
    }
    return hash;
}
// FNV-1a 64 (offset basis 0xcbf29ce484222325, prime 0x100000001b3) of `bytes`.
inline uint64_t fnv1a64(std::string_view bytes) { return fnv1a64Update(kFnv1a64Basis, bytes.data(), bytes.size()); }

// `value` as 16 lowercase hex digits.
std::string hex16(uint64_t value);

// Writes a file at `path` atomically: `write` fills a uniquely named temporary file in the same
// directory ("<file name>.tmp-<hex>"), which is then renamed over `path`, so readers see either
// the old file or the complete new one (concurrent writers: the last rename wins; a crash may
// leave a stale temporary). Creates the parent directory if needed; removes the temporary on any
// failure. Throws candela::UserError "PATH: problem" (one line, PATH = `path`) when the directory
// cannot be created, the temporary cannot be created or written (disk full), or the rename fails;
// an exception from `write` propagates (nothing is renamed).
void writeFileAtomically(const std::filesystem::path& path, const std::function<void(std::ostream& out)>& write);

}  // namespace candela
