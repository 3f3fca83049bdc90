// How the skin_morph pass splits a deformed draw for a device's limits
// (passes/deform/skin_morph_dispatch.h):
// 2-D group grids past maxComputeWorkGroupCount[0], bound ranges within maxStorageBufferRange with
// aligned offsets, every vertex covered once, in order.
#include "passes/deform/skin_morph_dispatch.h"
#include "vk/profile_caps.h"

#include "core/errors.h"

#include <gtest/gtest.h>

namespace candela::passes {
namespace {

constexpr uint64_t kVertexBytes = CANDELA_VERTEX_FLOATS * 4;

SkinMorphLimits minimumLimits() {
    vk::DeviceCaps device;  // a generous device, narrowed to what Vulkan 1.3 guarantees
    device.limits.maxStorageBufferRange = uint64_t(1) << 32;
    device.limits.minStorageBufferOffsetAlignment = 16;
    device.limits.maxComputeWorkGroupCount[0] = device.limits.maxComputeWorkGroupCount[1] = 1u << 30;
    return SkinMorphLimits::of(vk::narrowCaps(device, options::DeviceProfile::Minimum));
}

TEST(SkinMorphDispatch, MinimumProfileLimits) {
    const SkinMorphLimits limits = minimumLimits();
    EXPECT_EQ(limits.maxStorageBufferRange, uint64_t(128) << 20);
    EXPECT_EQ(limits.storageOffsetAlignment, 256u);
    EXPECT_EQ(limits.maxGroups[0], 65535u);
    EXPECT_EQ(limits.maxGroups[1], 65535u);
}

TEST(SkinMorphDispatch, FiveMillionVerticesSpreadOverXAndY) {
    const SkinMorphLimits limits = minimumLimits();
    const uint64_t vertices = 5'000'000;
    const GroupGrid grid = skinMorphGroups(vertices, limits.maxGroups);
    EXPECT_LE(grid.x, 65535u);
    EXPECT_LE(grid.y, 65535u);
    EXPECT_GT(grid.y, 1u);
    // Enough invocations, and no row without a vertex.
    EXPECT_GE(uint64_t(grid.x) * grid.y * CANDELA_SKIN_MORPH_GROUP_SIZE, vertices);
    EXPECT_LT(uint64_t(grid.x) * (grid.y - 1) * CANDELA_SKIN_MORPH_GROUP_SIZE, vertices);
    // Small counts stay one row, as before.
    EXPECT_EQ(skinMorphGroups(100, limits.maxGroups).x, 2u);
    EXPECT_EQ(skinMorphGroups(100, limits.maxGroups).y, 1u);
}

TEST(SkinMorphDispatch, TooManyGroupsIsAUserError) {
    const uint32_t tiny[2] = {2, 2};
    EXPECT_NO_THROW(skinMorphGroups(4 * CANDELA_SKIN_MORPH_GROUP_SIZE, tiny));
    EXPECT_THROW(skinMorphGroups(4 * CANDELA_SKIN_MORPH_GROUP_SIZE + 1, tiny), UserError);
}

// Every vertex of the job exactly once, in order, each range within the limit and aligned, and
// each push index pointing at the vertex's own bytes.
void expectCovers(const SkinMorphJob& job, const SkinMorphLimits& limits, const std::vector<SkinMorphDispatch>& dispatches) {
    uint64_t next = 0;
    for (const SkinMorphDispatch& d : dispatches) {
        for (const BufferRange& r : {d.vertices, d.deformation, d.deformed}) {
            EXPECT_EQ(r.offset % limits.storageOffsetAlignment, 0u);
            EXPECT_LE(r.size, limits.maxStorageBufferRange);
        }
        EXPECT_EQ(d.vertices.offset + d.push.sourceFloat * 4, (job.sourceFirstVertex + next) * kVertexBytes);
        EXPECT_EQ(d.vertices.size, d.push.sourceFloat * 4 + d.push.vertexCount * kVertexBytes);
        EXPECT_EQ(d.deformed.offset + d.push.targetFloat * 4, (job.targetFirstVertex + next) * kVertexBytes);
        EXPECT_EQ(d.deformation.offset + d.push.recordWord * 4, (job.recordWord + next * job.recordWords) * 4);
        EXPECT_EQ(d.deformation.size, (d.push.recordWord + uint64_t(d.push.vertexCount) * job.recordWords) * 4);
        EXPECT_GE(uint64_t(d.groups.x) * d.groups.y * CANDELA_SKIN_MORPH_GROUP_SIZE, d.push.vertexCount);
        EXPECT_EQ(d.push.groupsX, d.groups.x);
        next += d.push.vertexCount;
    }
    EXPECT_EQ(next, job.vertexCount);
}

TEST(SkinMorphDispatch, AVertexBufferPastTheStorageRangeIsSplit) {
    // 5 M skinned vertices (4 influences: 32-byte records) far into a 400 MB vertex buffer: more
    // than 128 MiB each, so several dispatches, each binding only its run.
    const SkinMorphLimits limits = minimumLimits();
    const SkinMorphJob job{.sourceFirstVertex = 555'555,
                           .vertexCount = 5'000'000,
                           .targetFirstVertex = 1'234'567,
                           .recordWord = 3'000'001,
                           .recordWords = 8,
                           .deltaWord = 8,
                           .influencesPerVertex = 4};
    const std::vector<SkinMorphDispatch> dispatches = skinMorphDispatches(job, limits);
    EXPECT_GE(dispatches.size(), 3u);
    expectCovers(job, limits, dispatches);
}

TEST(SkinMorphDispatch, ManyMorphTargetsSplitByTheirRecords) {
    SkinMorphLimits limits = minimumLimits();
    limits.maxStorageBufferRange = 64 * 1024;
    // 50 targets: 4,000-byte records, so 16 vertices a dispatch.
    const SkinMorphJob job{.sourceFirstVertex = 7, .vertexCount = 1000, .targetFirstVertex = 3, .recordWord = 5,
                           .recordWords = 50 * CANDELA_MORPH_DELTA_WORDS};
    const std::vector<SkinMorphDispatch> dispatches = skinMorphDispatches(job, limits);
    EXPECT_EQ(dispatches.size(), (1000 + 15) / 16);
    expectCovers(job, limits, dispatches);
}

TEST(SkinMorphDispatch, SmallDrawIsOneDispatch) {
    const SkinMorphJob job{.sourceFirstVertex = 10, .vertexCount = 1728, .recordWords = 8, .influencesPerVertex = 4};
    const std::vector<SkinMorphDispatch> dispatches = skinMorphDispatches(job, minimumLimits());
    ASSERT_EQ(dispatches.size(), 1u);
    EXPECT_EQ(dispatches[0].groups.x, 27u);
    EXPECT_EQ(dispatches[0].groups.y, 1u);
    expectCovers(job, minimumLimits(), dispatches);
}

TEST(SkinMorphDispatch, AVertexRecordPastTheRangeIsAOneLineError) {
    SkinMorphLimits limits = minimumLimits();
    limits.maxStorageBufferRange = 1024;
    const SkinMorphJob job{.vertexCount = 10, .recordWords = 20 * CANDELA_MORPH_DELTA_WORDS};  // 1,600-byte records
    try {
        skinMorphDispatches(job, limits);
        FAIL() << "no error";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("maxStorageBufferRange"), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
}

}  // namespace
}  // namespace candela::passes
