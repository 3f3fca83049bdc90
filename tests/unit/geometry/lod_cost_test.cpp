// When levels of detail are built (geometry/lod_cost.h, geometry/mesh_optimize.h): the cost model's
// decisions — a still never, the viewer always, --lod off never, a sequence once its frames at full
// detail cost more than the build, frames drawn before counting — and a deferred build giving the
// same chains as one at load.
#include "assets/builtin_scenes.h"
#include "geometry/lod_cost.h"
#include "geometry/mesh_optimize.h"
#include "bumpy_scene.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace candela::geometry {
namespace {

TEST(LodCost, AStillNeverBuildsTheViewerAlwaysDoes) {
    for (const bool cpu : {true, false}) {
        const TriangleCosts costs = measuredTriangleCosts(cpu);
        for (const uint64_t triangles : {100ull, 1'040'213ull, 50'000'000ull})
            for (const uint32_t cores : {1u, 2u, 4u}) {
                SCOPED_TRACE(testing::Message() << (cpu ? "CPU" : "GPU") << ", " << triangles << " triangles, " << cores << " cores");
                EXPECT_FALSE(decideLevelsOfDetail({triangles, triangles}, 0, 1, 0.5f, costs, cores).build);
                EXPECT_TRUE(decideLevelsOfDetail({triangles, triangles}, 0, std::nullopt, 0.5f, costs, cores).build);
                EXPECT_FALSE(decideLevelsOfDetail({triangles, triangles}, 0, std::nullopt, 0.0f, costs, cores).build) << "--lod off";
            }
    }
    EXPECT_FALSE(decideLevelsOfDetail({0, 0}, 0, std::nullopt, 0.5f, measuredTriangleCosts(true), 2).build) << "nothing to build";
}

TEST(LodCost, ASequenceBuildsOnceItsFramesCostMoreThanTheBuild) {
    // Build 3 µs a triangle on one core, draw 0.5 µs: on 2 cores the build (1.5 µs) pays from the 3rd frame.
    const TriangleCosts costs{.buildMicroseconds = 3.0, .drawMicroseconds = 0.5};
    EXPECT_FALSE(decideLevelsOfDetail({10'000, 10'000}, 0, 2, 0.5f, costs, 2).build);
    const LodDecision three = decideLevelsOfDetail({10'000, 10'000}, 0, 3, 0.5f, costs, 2);
    EXPECT_TRUE(three.build);
    EXPECT_EQ(three.reason, "levels of detail: built (drawing 10000 triangles at full detail for 3 frames costs about 15 ms on "
                            "this device, building their chains about 15 ms)");
    // Rent or buy: two stills drawn already and one more asked make three.
    EXPECT_TRUE(decideLevelsOfDetail({10'000, 10'000}, 2, 1, 0.5f, costs, 2).build);
    EXPECT_FALSE(decideLevelsOfDetail({10'000, 10'000}, 0, 3, 0.5f, costs, 1).build) << "one core: 30 ms to build";
    // On a GPU the frames that pay are thousands: the lavapipe figures' 0.55 against 0.001 µs.
    const TriangleCosts gpu = measuredTriangleCosts(false), cpu = measuredTriangleCosts(true);
    EXPECT_FALSE(decideLevelsOfDetail({10'000, 10'000}, 0, 1000, 0.5f, gpu, 2).build);
    EXPECT_TRUE(decideLevelsOfDetail({10'000, 10'000}, 0, 1000, 0.5f, cpu, 2).build);
}

TEST(LodCost, AMeshDrawnManyTimesIsBuiltOnceAndItsDrawsCounted) {
    // MetalRoughSpheresNoTextures' shape: one sphere of 10,600 triangles drawn by 98 nodes. Its
    // chain is built once (16 ms on 2 cores) and a still's frame draws it 98 times (571 ms on
    // lavapipe): a still pays.
    const TriangleCosts cpu = measuredTriangleCosts(true);
    const LodDecision still = decideLevelsOfDetail({.builtTriangles = 10'600, .drawnTriangles = 98 * 10'600}, 0, 1, 0.5f, cpu, 2);
    EXPECT_TRUE(still.build);
    EXPECT_EQ(still.reason, "levels of detail: built (drawing 1038800 triangles at full detail for 1 frame costs about 571 ms on "
                            "this device, building the chains of the 10600 distinct triangles about 16 ms)");
    // The work counts each draw and instance of a candidate, and each candidate once.
    scene::Scene scene = test::bumpyScene();
    prepareGeometry(scene, LevelsOfDetail::Defer);
    const LodWork once = lodCandidateWork(scene);
    scene::Draw copy = scene.draws[0];
    copy.instanceCount = 3;
    scene.draws.push_back(copy);
    const LodWork more = lodCandidateWork(scene);
    EXPECT_EQ(more.builtTriangles, once.builtTriangles);
    EXPECT_EQ(more.drawnTriangles, once.drawnTriangles + 3 * uint64_t(copy.indexCount / 3));
}

TEST(LodCost, ADeferredBuildGivesTheChainsOfABuildAtLoad) {
    scene::Scene now = test::bumpyScene(), later = test::bumpyScene();
    prepareGeometry(now, LevelsOfDetail::Build);
    prepareGeometry(later, LevelsOfDetail::Defer);
    EXPECT_FALSE(now.report.geometry.lodDeferred);
    EXPECT_TRUE(later.report.geometry.lodDeferred);
    EXPECT_TRUE(later.lodChains.empty());
    EXPECT_EQ(lodCandidateWork(later).builtTriangles, 2 * 3200u);
    EXPECT_EQ(lodCandidateWork(now).builtTriangles, 0u) << "every mesh has its chain";
    buildLevelsOfDetail(later, {}, 2);
    EXPECT_FALSE(later.report.geometry.lodDeferred);
    EXPECT_EQ(lodCandidateWork(later).builtTriangles, 0u);
    ASSERT_EQ(later.lodChains.size(), 2u);
    EXPECT_EQ(later.report.geometry.simplifiedMeshes, 2u);
    EXPECT_EQ(later.report.geometry.lodIndexBytes, now.report.geometry.lodIndexBytes);
    // The same levels (the chains in another order: the larger mesh first; here they tie).
    EXPECT_EQ(later.indices.size(), now.indices.size());
    for (size_t d = 0; d < now.draws.size(); ++d) {
        const scene::LodChain& a = now.lodChains[size_t(now.draws[d].lod)];
        const scene::LodChain& b = later.lodChains[size_t(later.draws[d].lod)];
        ASSERT_EQ(a.levels.size(), b.levels.size()) << "draw " << d;
        for (size_t i = 0; i < a.levels.size(); ++i) {
            EXPECT_EQ(a.levels[i].indexCount, b.levels[i].indexCount);
            EXPECT_EQ(a.levels[i].error, b.levels[i].error);
            EXPECT_TRUE(std::equal(now.indices.begin() + a.levels[i].firstIndex, now.indices.begin() + a.levels[i].firstIndex + a.levels[i].indexCount,
                                   later.indices.begin() + b.levels[i].firstIndex));
        }
    }
    EXPECT_EQ(now.draws[0].lod, now.draws[1].lod) << "one chain for the two draws of one mesh";
    // The built-in grid comes with its chain: nothing to defer.
    scene::Scene grid = assets::makeSphereGrid();
    EXPECT_EQ(lodCandidateWork(grid).builtTriangles, 0u);
}

}  // namespace
}  // namespace candela::geometry
