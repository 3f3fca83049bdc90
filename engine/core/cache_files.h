#pragma once
// What Candela's on-disk caches share (the IBL maps: ibl/ibl_cache_file.h; compiled pipelines:
// vk/pipeline_cache_file.h; levels of detail: geometry/lod_cache_file.h): the user's cache folder,
// the hashes their files are keyed and checksummed with, writing a file atomically, and evicting
// the least recently used files beyond a cap. No Vulkan.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

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
// The levels-of-detail cache's folder a choice names (--lod-cache, DeviceOptions::lodCache): the
// same as iblCacheFolder with the user's cache folder's "lod" folder.
std::filesystem::path lodCacheFolder(const std::string& choice);

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

// A 64-bit hash of `size` bytes at `bytes` for keying and checksumming caches by large contents (a
// mesh's positions and indices, an environment's texels, a cache file's bytes), continuing from
// `hash` (0 to start): the bytes as little-endian 64-bit words (the last one zero-padded, the
// length mixed in), each multiplied into the state and the state's bits folded down — several bytes
// a cycle where fnv1a64 takes one. Not for security; like fnv1a64, its value is part of cache file
// names and must not change.
uint64_t wordHash64(uint64_t hash, const void* bytes, size_t size);

// wordHash64 of bytes given in pieces: value() is wordHash64(seed, every byte given so far, in
// order), however they were split — for the checksum of a file written and read field by field.
class WordHasher {
public:
    explicit WordHasher(uint64_t seed = 0) : mHash(seed) {}
    void update(const void* bytes, size_t size);
    uint64_t value() const;

private:
    uint64_t mHash;
    uint64_t mPending = 0;        // the bytes of the word begun, little-endian
    unsigned mPendingBytes = 0;   // 0..7
    uint64_t mSize = 0;           // bytes given so far
};

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

// Marks the cache file at `path` as just used (its last write time: now), so that evictCacheFiles
// removes it after the files used longer ago. Errors are ignored (the file is then older than it
// should be).
void touchCacheFile(const std::filesystem::path& path);

// Removes the least recently used files of `dir` whose extension is `extension` (".cibl"; by last
// write time: written, or touched when read) until those left take at most `capBytes` — never
// `keep` (the file just written, which alone may exceed the cap). Returns the files removed. A
// file another process removed or cannot be removed is skipped; never throws for the folder's state.
std::vector<std::filesystem::path> evictCacheFiles(const std::filesystem::path& dir, std::string_view extension,
                                                   uint64_t capBytes, const std::filesystem::path& keep);

}  // namespace candela
