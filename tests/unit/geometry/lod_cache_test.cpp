// Levels of detail with the on-disk cache (geometry/lod_cache.h): stills of one scene in fresh
// "runs" record their frames until drawing every run's frames at full detail costs more than
// building, the run that builds stores the chains, and later runs read the very chains it built;
// the key follows the meshes' positions and indices and the settings; a damaged file is ignored
// and replaced; no folder or --lod off writes nothing.
#include "geometry/lod_cache.h"
#include "bumpy_scene.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <fstream>

namespace candela::geometry {
namespace {

namespace fs = std::filesystem;

// One core, lavapipe's costs: the bumpy scene's 6,400 triangles take 19.2 ms to build, and its
// 9,600 triangles drawn (one mesh drawn twice) 5.28 ms a frame at full detail, so building pays
// from the fourth frame.
const TriangleCosts kCosts{.buildMicroseconds = 3.0, .drawMicroseconds = 0.55};

// A fresh load of the bumpy scene, its levels deferred (a new process's).
scene::Scene loaded(float bump = 0.3f) {
    scene::Scene s = test::bumpyScene(bump);
    prepareGeometry(s, LevelsOfDetail::Defer);
    return s;
}

// The indices of every level of every draw's chain, in draw order.
std::vector<std::vector<uint32_t>> levelsOf(const scene::Scene& s) {
    std::vector<std::vector<uint32_t>> out;
    for (const scene::Draw& draw : s.draws) {
        if (draw.lod < 0) continue;
        for (const scene::LodLevel& level : s.lodChains[size_t(draw.lod)].levels)
            out.emplace_back(s.indices.begin() + level.firstIndex, s.indices.begin() + level.firstIndex + level.indexCount);
    }
    return out;
}

size_t filesIn(const fs::path& dir) {
    std::error_code ec;
    size_t n = 0;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) ++n;
    return n;
}

TEST(LodCache, StillsRecordTheirFramesUntilBuildingPaysThenLaterRunsReadTheChains) {
    test::TempDir dir("candela_lod_cache");
    std::vector<std::vector<uint32_t>> built;
    for (int run = 1; run <= 7; ++run) {
        scene::Scene s = loaded();
        const LodDecision decision = provideLevelsOfDetail(s, 0, 1, 0.5f, kCosts, 1, dir.path());
        SCOPED_TRACE("run " + std::to_string(run) + ": " + decision.reason);
        // bumpyScene: 6,400 triangles to build (19.2 ms on one core), 9,600 drawn a frame (one mesh
        // twice: 5.3 ms): the fourth frame pays.
        if (run < 4) {
            EXPECT_FALSE(decision.build);
            EXPECT_TRUE(s.report.geometry.lodDeferred);
            EXPECT_TRUE(s.lodChains.empty());
            EXPECT_TRUE(decision.reason.starts_with("levels of detail: not built"));
            if (run > 1) {
                EXPECT_NE(decision.reason.find("; " + std::to_string(run - 1) + " of the frames drawn before, as the cache records)"),
                          std::string::npos);
            }
        } else if (run == 4) {
            EXPECT_TRUE(decision.build);
            EXPECT_TRUE(decision.reason.starts_with("levels of detail: built (drawing 9600 triangles at full detail for 4 frames"));
            built = levelsOf(s);
        } else {
            EXPECT_TRUE(decision.build);
            EXPECT_TRUE(decision.reason.starts_with("levels of detail: read from the cache (" + dir.path().string()));
            EXPECT_FALSE(s.report.geometry.lodDeferred);
            EXPECT_EQ(s.report.geometry.simplifiedMeshes, 2u);
            EXPECT_EQ(levelsOf(s), built) << "the chains the building run made";
        }
        EXPECT_EQ(filesIn(dir.path()), 1u) << "one file for the scene, no temporary left";
    }
    // The same chains as a build at load.
    scene::Scene atLoad = test::bumpyScene();
    prepareGeometry(atLoad, LevelsOfDetail::Build);
    EXPECT_EQ(levelsOf(atLoad), built);
}

TEST(LodCache, FramesOfThisProcessAndOfEarlierRunsAreNotCountedTwice) {
    test::TempDir dir("candela_lod_cache");
    scene::Scene s = loaded();
    // This process draws 1 frame, then 2 (the record then holds 1, then 3): 3 before the next call, not 4.
    EXPECT_FALSE(provideLevelsOfDetail(s, 0, 1, 0.5f, kCosts, 1, dir.path()).build);
    EXPECT_FALSE(provideLevelsOfDetail(s, 1, 2, 0.5f, kCosts, 1, dir.path()).build);
    const LodDecision fourth = provideLevelsOfDetail(s, 3, 1, 0.5f, kCosts, 1, dir.path());
    EXPECT_TRUE(fourth.build) << fourth.reason;
    EXPECT_NE(fourth.reason.find("for 4 frames"), std::string::npos) << fourth.reason;
}

TEST(LodCache, TheKeyFollowsPositionsIndicesAndSettings) {
    const scene::Scene a = loaded(), same = loaded(), bumpier = loaded(0.31f);
    const std::vector<LodCandidate> candidates = lodCandidates(a);
    ASSERT_EQ(candidates.size(), 2u);
    const LodCacheKey key = lodCacheKey(a, candidates, {});
    EXPECT_EQ(lodCacheKey(same, lodCandidates(same), {}).contentHash, key.contentHash);
    EXPECT_NE(lodCacheKey(bumpier, lodCandidates(bumpier), {}).contentHash, key.contentHash);
    scene::Scene flipped = loaded();
    std::swap(flipped.indices[0], flipped.indices[1]);
    EXPECT_NE(lodCacheKey(flipped, lodCandidates(flipped), {}).contentHash, key.contentHash);
    // Normals and UVs do not change the chains: not in the key.
    scene::Scene uv = loaded();
    uv.vertices[0].uv0 = glm::vec2(0.5f);
    EXPECT_EQ(lodCacheKey(uv, lodCandidates(uv), {}).contentHash, key.contentHash);
    LodChainSettings finer;
    finer.reduction = 0.5f;
    EXPECT_NE(lodCacheKey(a, candidates, finer).settings, key.settings);
    EXPECT_TRUE(key.settings.starts_with(
        "chain=1 reduction=0.33333334 minimum-gain=0.6 max-extra-indices=0.5 max-levels=8 min-triangles=8 meshoptimizer="))
        << key.settings;
}

TEST(LodCache, ADamagedFileIsIgnoredAndReplaced) {
    test::TempDir dir("candela_lod_cache");
    scene::Scene s = loaded();
    const fs::path path = lodCacheFilePath(dir.path(), lodCacheKey(s, lodCandidates(s), {}));
    std::ofstream(path, std::ios::binary) << "CANDELA-LOD garbage";
    const LodDecision decision = provideLevelsOfDetail(s, 0, 1, 0.5f, kCosts, 1, dir.path());
    EXPECT_FALSE(decision.build);
    EXPECT_NE(decision.reason.find("; ignored " + path.string() + ": "), std::string::npos) << decision.reason;
    std::string why;
    const std::optional<LodCacheRecord> record =
        readLodCacheFile(path, lodCacheKey(s, lodCandidates(s), {}), std::vector<LodCacheMesh>(2, {1681, 9600}), &why);
    ASSERT_TRUE(record) << why;
    EXPECT_EQ(record->framesDrawn, 1u);
}

TEST(LodCache, NoFolderOrLevelsOffWriteNothing) {
    test::TempDir dir("candela_lod_cache");
    scene::Scene s = loaded();
    EXPECT_EQ(provideLevelsOfDetail(s, 0, 100, 0.0f, kCosts, 1, dir.path()).reason, "levels of detail: not built (--lod off)");
    EXPECT_EQ(filesIn(dir.path()), 0u);
    const LodDecision decision = provideLevelsOfDetail(s, 0, 100, 0.5f, kCosts, 1, {});
    EXPECT_TRUE(decision.build) << decision.reason;
    EXPECT_FALSE(s.report.geometry.lodDeferred);
    EXPECT_EQ(filesIn(dir.path()), 0u);
}

TEST(LodCache, AFolderThatCannotBeWrittenCostsOnlyANote) {
    test::TempDir dir("candela_lod_cache");
    const fs::path blocked = dir.path() / "file";
    std::ofstream(blocked) << "not a folder";
    scene::Scene s = loaded();
    const LodDecision decision = provideLevelsOfDetail(s, 0, 100, 0.5f, kCosts, 1, blocked / "lod");
    EXPECT_TRUE(decision.build);
    EXPECT_NE(decision.reason.find("; not cached: "), std::string::npos) << decision.reason;
}

}  // namespace
}  // namespace candela::geometry
