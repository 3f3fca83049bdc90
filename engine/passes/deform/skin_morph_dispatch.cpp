#include "passes/deform/skin_morph_dispatch.h"

#include "core/errors.h"

#include <algorithm>
#include <string>

namespace candela::passes {
namespace {

constexpr uint64_t kVertexBytes = CANDELA_VERTEX_FLOATS * 4;
constexpr uint64_t kGroup = CANDELA_SKIN_MORPH_GROUP_SIZE;

// The range holding `count` elements of `elementBytes` from byte `start`, its offset aligned down,
// and where `start` lies in it (in 4-byte words).
struct Bound {
    BufferRange range;
    uint32_t word = 0;
};
Bound bind(uint64_t start, uint64_t count, uint64_t elementBytes, uint64_t alignment) {
    const uint64_t offset = start - start % alignment;
    return {.range = {.offset = offset, .size = start - offset + count * elementBytes}, .word = uint32_t((start - offset) / 4)};
}

}  // namespace

SkinMorphLimits SkinMorphLimits::of(const vk::DeviceCaps& caps) {
    return {.maxStorageBufferRange = caps.limits.maxStorageBufferRange,
            .storageOffsetAlignment = std::max<uint64_t>(caps.limits.minStorageBufferOffsetAlignment, 1),
            .maxGroups = {caps.limits.maxComputeWorkGroupCount[0], caps.limits.maxComputeWorkGroupCount[1]}};
}

GroupGrid skinMorphGroups(uint64_t vertices, const uint32_t maxGroups[2]) {
    const uint64_t groups = (vertices + kGroup - 1) / kGroup;
    if (groups == 0) return {.x = 1, .y = 1};
    const uint64_t x = std::min<uint64_t>(groups, maxGroups[0]);
    const uint64_t y = x == 0 ? 0 : (groups + x - 1) / x;
    if (x == 0 || y > maxGroups[1])
        throw UserError("skin_morph: " + std::to_string(vertices) + " vertices need " + std::to_string(groups) +
                        " groups, more than the device's maxComputeWorkGroupCount allows (" +
                        std::to_string(maxGroups[0]) + " x " + std::to_string(maxGroups[1]) + ")");
    return {.x = uint32_t(x), .y = uint32_t(y)};
}

std::vector<SkinMorphDispatch> skinMorphDispatches(const SkinMorphJob& job, const SkinMorphLimits& limits) {
    // The most vertices one dispatch may take: each bound range, at its worst alignment slack, must
    // fit in maxStorageBufferRange, and the groups in the X × Y grid.
    const uint64_t recordBytes = uint64_t(job.recordWords) * 4;
    const uint64_t slack = limits.storageOffsetAlignment - std::min<uint64_t>(limits.storageOffsetAlignment, 4);
    const uint64_t usable = limits.maxStorageBufferRange > slack ? limits.maxStorageBufferRange - slack : 0;
    uint64_t perDispatch = usable / std::max(kVertexBytes, recordBytes);
    perDispatch = std::min(perDispatch, uint64_t(limits.maxGroups[0]) * limits.maxGroups[1] * kGroup);
    if (perDispatch == 0)
        throw UserError("skin_morph: one vertex's skin and morph data (" + formatBytes(std::max(kVertexBytes, recordBytes)) +
                        ") does not fit in the device's maxStorageBufferRange (" +
                        formatBytes(limits.maxStorageBufferRange) + ")");
    std::vector<SkinMorphDispatch> out;
    for (uint64_t first = 0; first < job.vertexCount; first += perDispatch) {
        const uint64_t count = std::min<uint64_t>(perDispatch, job.vertexCount - first);
        const Bound vertices = bind((job.sourceFirstVertex + first) * kVertexBytes, count, kVertexBytes, limits.storageOffsetAlignment);
        const Bound deformed = bind((job.targetFirstVertex + first) * kVertexBytes, count, kVertexBytes, limits.storageOffsetAlignment);
        // A draw with neither influences nor targets reads no record: it binds the buffer's first word.
        const Bound records = recordBytes == 0 ? Bound{.range = {.offset = 0, .size = 4}}
                                               : bind((job.recordWord + first * job.recordWords) * 4, count, recordBytes,
                                                      limits.storageOffsetAlignment);
        SkinMorphDispatch d{.vertices = vertices.range, .deformation = records.range, .deformed = deformed.range,
                            .groups = skinMorphGroups(count, limits.maxGroups)};
        d.push = {.vertexCount = uint32_t(count),
                  .groupsX = d.groups.x,
                  .sourceFloat = vertices.word,
                  .targetFloat = deformed.word,
                  .recordWord = records.word,
                  .recordWords = job.recordWords,
                  .deltaWord = job.deltaWord,
                  .influencesPerVertex = job.influencesPerVertex,
                  .jointWord = job.jointWord,
                  .activeWord = job.activeWord,
                  .activeCount = job.activeCount,
                  .pad0 = 0};
        out.push_back(d);
    }
    return out;
}

}  // namespace candela::passes
