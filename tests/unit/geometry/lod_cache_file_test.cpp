// The levels-of-detail cache file (geometry/lod_cache_file.h): a record round-trips, with chains or
// with a frame count alone; any truncation, any flipped bit, another key, chains for other meshes
// and indices beyond a mesh's vertices are misses with a reason, never a crash or a bad record.
#include "geometry/lod_cache_file.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <fstream>

namespace candela::geometry {
namespace {

namespace fs = std::filesystem;

const LodCacheKey kKey{0x0123456789abcdefull, "chain=1 reduction=0.33333334"};
const std::vector<LodCacheMesh> kMeshes = {{.vertexCount = 10, .indexCount = 24}, {.vertexCount = 4, .indexCount = 6}};

LodCacheRecord withChains() {
    LodCacheRecord record;
    record.framesDrawn = 7;
    record.chains.emplace();
    record.chains->push_back({{{0, 1, 2, 3, 4, 9, 5, 6, 7, 7, 8, 9}, 0.25f}, {{0, 4, 9}, 0.5f}});
    record.chains->push_back({});  // the second mesh does not simplify
    return record;
}

void expectSame(const LodCacheRecord& a, const LodCacheRecord& b) {
    EXPECT_EQ(a.framesDrawn, b.framesDrawn);
    ASSERT_EQ(a.chains.has_value(), b.chains.has_value());
    if (!a.chains) return;
    ASSERT_EQ(a.chains->size(), b.chains->size());
    for (size_t m = 0; m < a.chains->size(); ++m) {
        ASSERT_EQ((*a.chains)[m].size(), (*b.chains)[m].size());
        for (size_t l = 0; l < (*a.chains)[m].size(); ++l) {
            EXPECT_EQ((*a.chains)[m][l].indices, (*b.chains)[m][l].indices);
            EXPECT_EQ((*a.chains)[m][l].error, (*b.chains)[m][l].error);
        }
    }
}

TEST(LodCacheFile, ARecordRoundTripsWithChainsOrFramesAlone) {
    for (const LodCacheRecord& record : {withChains(), LodCacheRecord{.framesDrawn = 3, .chains = std::nullopt}}) {
        const std::vector<std::byte> bytes = encodeLodCache(kKey, record);
        std::string why;
        const std::optional<LodCacheRecord> read = parseLodCache(bytes, kKey, kMeshes, &why);
        ASSERT_TRUE(read) << why;
        expectSame(*read, record);
    }
    // Through a file, under the name the key gives.
    test::TempDir dir("candela_lod_cache_file");
    const fs::path path = lodCacheFilePath(dir.path(), kKey);
    EXPECT_EQ(path.filename().string().substr(0, 17), "0123456789abcdef-");
    EXPECT_EQ(path.extension(), ".clod");
    writeLodCacheFile(path, kKey, withChains());
    std::string why;
    const std::optional<LodCacheRecord> read = readLodCacheFile(path, kKey, kMeshes, &why);
    ASSERT_TRUE(read) << why;
    expectSame(*read, withChains());
    // A missing file: a miss naming it.
    EXPECT_FALSE(readLodCacheFile(dir.path() / "none.clod", kKey, kMeshes, &why));
    EXPECT_NE(why.find("none.clod: "), std::string::npos) << why;
}

TEST(LodCacheFile, EveryTruncationAndEveryFlippedBitIsAMiss) {
    const std::vector<std::byte> bytes = encodeLodCache(kKey, withChains());
    for (size_t size = 0; size < bytes.size(); ++size) {
        std::string why;
        EXPECT_FALSE(parseLodCache(std::span(bytes).first(size), kKey, kMeshes, &why)) << size;
        EXPECT_FALSE(why.empty()) << size;
    }
    for (size_t i = 0; i < bytes.size(); ++i)
        for (int bit = 0; bit < 8; ++bit) {
            std::vector<std::byte> flipped = bytes;
            flipped[i] ^= std::byte(1 << bit);
            EXPECT_FALSE(parseLodCache(flipped, kKey, kMeshes, nullptr)) << "byte " << i << " bit " << bit;
        }
    std::vector<std::byte> longer = bytes;
    longer.push_back(std::byte{0});
    std::string why;
    EXPECT_FALSE(parseLodCache(longer, kKey, kMeshes, &why));
    EXPECT_EQ(why, "1 unexpected bytes after the checksum");
}

TEST(LodCacheFile, AnotherKeyOrOtherMeshesIsAMiss) {
    const std::vector<std::byte> bytes = encodeLodCache(kKey, withChains());
    std::string why;
    EXPECT_FALSE(parseLodCache(bytes, {kKey.contentHash + 1, kKey.settings}, kMeshes, &why));
    EXPECT_EQ(why, "made for other meshes or settings");
    EXPECT_FALSE(parseLodCache(bytes, {kKey.contentHash, kKey.settings + " "}, kMeshes, &why));
    EXPECT_EQ(why, "made for other meshes or settings");
    // The same key, but the meshes are not those the chains were made for (a hash collision).
    EXPECT_FALSE(parseLodCache(bytes, kKey, std::span(kMeshes).first(1), &why));
    EXPECT_EQ(why, "chains of 2 meshes for 1");
    const std::vector<LodCacheMesh> fewerVertices = {{.vertexCount = 9, .indexCount = 24}, kMeshes[1]};
    EXPECT_FALSE(parseLodCache(bytes, kKey, fewerVertices, &why));
    EXPECT_EQ(why, "mesh 0: level 1: index 9 is beyond the mesh's 9 vertices");
    const std::vector<LodCacheMesh> fewerIndices = {{.vertexCount = 10, .indexCount = 12}, kMeshes[1]};
    EXPECT_FALSE(parseLodCache(bytes, kKey, fewerIndices, &why));
    EXPECT_EQ(why, "mesh 0: level 1: 12 indices: not a positive multiple of 3 below the finer level's 12");
    // A frame count alone fits any meshes.
    EXPECT_TRUE(parseLodCache(encodeLodCache(kKey, {.framesDrawn = 1, .chains = std::nullopt}), kKey, {}, &why)) << why;
}

TEST(LodCacheFile, LevelsThatBreakTheLayoutsRulesAreMisses) {
    std::string why;
    const auto parsed = [&](std::vector<SimplifiedLevel> chain) {
        LodCacheRecord record;
        record.chains.emplace();
        record.chains->push_back(std::move(chain));
        record.chains->push_back({});
        return parseLodCache(encodeLodCache(kKey, record), kKey, kMeshes, &why).has_value();
    };
    EXPECT_TRUE(parsed({{{0, 1, 2}, 0.0f}})) << why;
    EXPECT_FALSE(parsed({{{0, 1}, 0.0f}}));
    EXPECT_EQ(why, "mesh 0: level 1: 2 indices: not a positive multiple of 3 below the finer level's 24");
    EXPECT_FALSE(parsed({{{0, 1, 2}, -1.0f}}));
    EXPECT_FALSE(parsed({{{0, 1, 2}, std::numeric_limits<float>::quiet_NaN()}}));
    EXPECT_FALSE(parsed({{{0, 1, 2, 3, 4, 5}, 0.5f}, {{0, 1, 2}, 0.25f}})) << "an error below the finer level's";
    EXPECT_EQ(why, "mesh 0: level 2: error 0.250000 is not finite or below the finer level's");
    EXPECT_FALSE(parsed({{{0, 1, 2}, 0.5f}, {{0, 1, 2}, 0.5f}})) << "no fewer indices than the finer level";
}

}  // namespace
}  // namespace candela::geometry
