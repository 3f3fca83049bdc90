#include "geometry/lod_cache_file.h"

#include "core/cache_fields.h"
#include "core/cache_files.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace candela::geometry {
namespace {

namespace fs = std::filesystem;

constexpr std::array<char, 12> kMagic = {'C', 'A', 'N', 'D', 'E', 'L', 'A', '-', 'L', 'O', 'D', '\0'};
// Files larger than this are not read (the chains of a 100 M-triangle scene are smaller).
constexpr uint64_t kMaxFileBytes = uint64_t(4) << 30;

// Appends what a CacheFieldWriter writes to `out`.
struct BytesSink {
    std::vector<std::byte>* out;
    void operator()(const void* data, size_t size) const {
        const auto* p = static_cast<const std::byte*>(data);
        out->insert(out->end(), p, p + size);
    }
};

using Reader = CacheFieldReader<CacheBytesSource>;

// Reads mesh `m`'s levels into `levels`, checking them against `mesh`.
bool readChain(Reader& in, uint32_t m, const LodCacheMesh& mesh, std::vector<SimplifiedLevel>& levels) {
    const std::string where = "mesh " + std::to_string(m) + ": ";
    uint32_t count = 0;
    if (!in.u32(count, "a level count")) return false;
    if (count > kLodCacheMaxLevels)
        return in.fail(where + std::to_string(count) + " levels, more than " + std::to_string(kLodCacheMaxLevels));
    levels.resize(count);
    uint32_t finer = mesh.indexCount;
    float finerError = 0.0f;
    for (uint32_t l = 0; l < count; ++l) {
        SimplifiedLevel& level = levels[l];
        uint32_t errorBits = 0, indices = 0;
        if (!in.u32(errorBits, "a level's error") || !in.u32(indices, "a level's index count")) return false;
        level.error = std::bit_cast<float>(errorBits);
        const std::string at = where + "level " + std::to_string(l + 1) + ": ";
        if (!std::isfinite(level.error) || level.error < finerError)
            return in.fail(at + "error " + std::to_string(level.error) + " is not finite or below the finer level's");
        if (indices == 0 || indices % 3 != 0 || indices >= finer)
            return in.fail(at + std::to_string(indices) + " indices: not a positive multiple of 3 below the finer level's " +
                           std::to_string(finer));
        if (uint64_t(indices) * 4 > in.remaining()) return in.fail(at + "truncated: the file ends inside its indices");
        level.indices.resize(indices);
        for (uint32_t& index : level.indices) {
            in.u32(index, "an index");  // within the bytes left: checked above
            if (index >= mesh.vertexCount)
                return in.fail(at + "index " + std::to_string(index) + " is beyond the mesh's " +
                               std::to_string(mesh.vertexCount) + " vertices");
        }
        finer = indices;
        finerError = level.error;
    }
    return true;
}

}  // namespace

fs::path lodCacheFilePath(const fs::path& dir, const LodCacheKey& key) {
    return dir / (hex16(key.contentHash) + "-" + hex16(fnv1a64(key.settings)) + ".clod");
}

std::vector<std::byte> encodeLodCache(const LodCacheKey& key, const LodCacheRecord& record) {
    if (key.settings.size() > kLodCacheMaxSettingsLength) throw std::invalid_argument("LOD cache: settings text too long");
    std::vector<std::byte> bytes;
    CacheFieldWriter out(BytesSink{&bytes});
    out.bytes(kMagic.data(), kMagic.size());
    out.u32(kLodCacheVersion);
    out.u64(key.contentHash);
    out.u32(uint32_t(key.settings.size()));
    out.bytes(key.settings.data(), key.settings.size());
    out.u64(record.framesDrawn);
    out.u32(record.chains ? uint32_t(record.chains->size()) : 0u);
    if (record.chains)
        for (const std::vector<SimplifiedLevel>& chain : *record.chains) {
            if (chain.size() > kLodCacheMaxLevels) throw std::invalid_argument("LOD cache: too many levels");
            out.u32(uint32_t(chain.size()));
            for (const SimplifiedLevel& level : chain) {
                out.u32(std::bit_cast<uint32_t>(level.error));
                out.u32(uint32_t(level.indices.size()));
                for (uint32_t i : level.indices) out.u32(i);
            }
        }
    out.u64(out.hash());  // the checksum
    return bytes;
}

void writeLodCacheFile(const fs::path& path, const LodCacheKey& key, const LodCacheRecord& record) {
    const std::vector<std::byte> bytes = encodeLodCache(key, record);
    writeFileAtomically(path, [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    });
}

std::optional<LodCacheRecord> parseLodCache(std::span<const std::byte> bytes, const LodCacheKey& key,
                                            std::span<const LodCacheMesh> meshes, std::string* reason) {
    Reader in(bytes.size(), CacheBytesSource{bytes});
    const auto miss = [&](const std::string& why) -> std::optional<LodCacheRecord> {
        if (reason) *reason = why;
        return std::nullopt;
    };
    std::array<char, 12> magic{};
    if (!in.bytes(magic.data(), magic.size(), "the magic")) return miss(in.problem());
    if (magic != kMagic) return miss("not a levels-of-detail cache file (bad magic)");
    uint32_t version = 0;
    if (!in.u32(version, "the version")) return miss(in.problem());
    if (version != kLodCacheVersion)
        return miss("version " + std::to_string(version) + ", this build reads " + std::to_string(kLodCacheVersion));
    uint64_t contentHash = 0;
    uint32_t settingsLength = 0;
    if (!in.u64(contentHash, "the content hash") || !in.u32(settingsLength, "the settings' length")) return miss(in.problem());
    if (settingsLength > kLodCacheMaxSettingsLength) return miss("settings text of " + std::to_string(settingsLength) + " bytes");
    std::string settings(settingsLength > in.remaining() ? 0 : settingsLength, '\0');
    if (!in.bytes(settings.data(), settingsLength, "the settings")) return miss(in.problem());
    if (contentHash != key.contentHash || settings != key.settings) return miss("made for other meshes or settings");
    LodCacheRecord record;
    uint32_t meshCount = 0;
    if (!in.u64(record.framesDrawn, "the frame count") || !in.u32(meshCount, "the mesh count")) return miss(in.problem());
    if (meshCount != 0) {
        if (meshCount != meshes.size())
            return miss("chains of " + std::to_string(meshCount) + " meshes for " + std::to_string(meshes.size()));
        record.chains.emplace(meshCount);
        for (uint32_t m = 0; m < meshCount; ++m)
            if (!readChain(in, m, meshes[m], (*record.chains)[m])) return miss(in.problem());
    }
    const uint64_t contents = in.hash();
    uint64_t checksum = 0;
    if (!in.u64(checksum, "the checksum")) return miss(in.problem());
    if (in.remaining() != 0) return miss(std::to_string(in.remaining()) + " unexpected bytes after the checksum");
    if (checksum != contents) return miss("checksum mismatch: corrupt file");
    return record;
}

std::optional<LodCacheRecord> readLodCacheFile(const fs::path& path, const LodCacheKey& key,
                                               std::span<const LodCacheMesh> meshes, std::string* reason) {
    const auto miss = [&](const std::string& why) -> std::optional<LodCacheRecord> {
        if (reason) *reason = path.string() + ": " + why;
        return std::nullopt;
    };
    std::error_code ec;
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) return miss(ec.message());
    if (size > kMaxFileBytes) return miss(std::to_string(size) + " bytes, more than a cache file holds");
    std::vector<std::byte> bytes(size);
    std::ifstream in(path, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size))) return miss("cannot be read");
    std::string why;
    std::optional<LodCacheRecord> record = parseLodCache(bytes, key, meshes, &why);
    if (!record) return miss(why);
    return record;
}

}  // namespace candela::geometry
