#pragma once
// How the skin_morph pass splits one deformed draw into dispatches a device can run: each dispatch
// binds only the ranges of the scene's vertex and deformation buffers and of the output that its
// vertices need (offsets aligned to minStorageBufferOffsetAlignment, sizes within
// maxStorageBufferRange), and spreads its groups over X and Y within maxComputeWorkGroupCount.
// A draw too big for one dispatch becomes several runs of consecutive vertices.
//
// Pure: no Vulkan calls (unit-tested with the minimum profile's limits).

#include "shared/skin_morph.h"
#include "vk/device_caps.h"

#include <cstdint>
#include <vector>

namespace candela::passes {

// The limits the split obeys.
struct SkinMorphLimits {
    uint64_t maxStorageBufferRange = 0;
    uint64_t storageOffsetAlignment = 1;  // a power of two
    uint32_t maxGroups[2] = {0, 0};       // maxComputeWorkGroupCount X, Y
    static SkinMorphLimits of(const vk::DeviceCaps& caps);
};

// One deformed draw, in whole-buffer terms (what skinMorphFrame builds).
struct SkinMorphJob {
    uint32_t sourceFirstVertex = 0;    // its vertex range in the scene's vertex buffer
    uint32_t vertexCount = 0;
    uint32_t targetFirstVertex = 0;    // where its deformed copy starts in the deformed-vertex buffer
    uint64_t recordWord = 0;           // deformation-buffer word of its vertex 0's record
    uint32_t recordWords = 0;          // words per vertex record (GpuScene::deformationRecordWords)
    uint32_t deltaWord = 0;            // where the deltas start in a record
    uint32_t influencesPerVertex = 0;  // 0: not skinned
    uint32_t jointWord = 0;            // frame-data word of its skin's first joint matrix
    uint32_t activeWord = 0;           // frame-data word of its first non-zero morph weight
    uint32_t activeCount = 0;
};

// A byte range of a buffer as a descriptor binds it.
struct BufferRange {
    uint64_t offset = 0;
    uint64_t size = 0;
};

struct GroupGrid {
    uint32_t x = 0, y = 0;
};

// One dispatch: its push constants (indices relative to the ranges) and what it binds.
struct SkinMorphDispatch {
    shading::SkinMorphPush push{};
    BufferRange vertices;     // of the scene's vertex buffer
    BufferRange deformation;  // of the scene's deformation buffer (its first word when the draw reads none)
    BufferRange deformed;     // of the deformed-vertex buffer
    GroupGrid groups;
};

// The groups for `vertices` invocations in groups of CANDELA_SKIN_MORPH_GROUP_SIZE: all in X when
// they fit, else X full and as many rows in Y as needed (x × y × group size ≥ vertices, and the last
// row is not empty). Throws UserError when even X × Y groups cannot hold them.
GroupGrid skinMorphGroups(uint64_t vertices, const uint32_t maxGroups[2]);

// `job` split into dispatches that cover its vertices in order, each exactly once. Throws UserError
// (one line, naming the limit) when a single vertex's record does not fit in maxStorageBufferRange.
std::vector<SkinMorphDispatch> skinMorphDispatches(const SkinMorphJob& job, const SkinMorphLimits& limits);

}  // namespace candela::passes
