// Step "barriers": walks the passes in execution order, tracks per resource its layout, its last
// write and the reads synchronised since, and emits the synchronization2 barriers each pass needs.

#include "graph/compile_steps.h"

#include <algorithm>

namespace candela::graph::detail {

namespace {

// All accesses of one pass to one resource, merged into a single barrier endpoint.
struct MergedAccess {
    uint32_t resource = kInvalidIndex;
    ResourceState state;
    bool writes = false;
};

// Synchronisation state of one resource between passes.
struct Track {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    bool written = false;  // a write (or layout transition) precedes the current point
    VkPipelineStageFlags2 writeStages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 writeAccess = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 readStages = VK_PIPELINE_STAGE_2_NONE;  // synchronised since the write
    VkAccessFlags2 readAccess = VK_ACCESS_2_NONE;
    bool touched = false;  // accessed by a pass of this graph
    ResourceState last;    // the last access, for finalStates
};

bool isSubset(VkFlags64 flags, VkFlags64 of) { return (flags & ~of) == 0; }

std::vector<MergedAccess> mergeAccesses(const GraphDecl& decl, const PassDecl& pass) {
    std::vector<MergedAccess> merged;
    for (const auto* list : {&pass.reads, &pass.writes}) {
        for (const AccessDecl& access : *list) {
            auto it = std::find_if(merged.begin(), merged.end(), [&](const MergedAccess& m) {
                return m.resource == access.resource;
            });
            if (it == merged.end())
                it = merged.insert(merged.end(), {access.resource, passAccessState(decl, pass, access.resource), false});
            it->writes = it->writes || list == &pass.writes || usageWrites(access.usage);
        }
    }
    return merged;
}

Track initialTrack(const ResourceDecl& resource) {
    Track track;
    if (!resource.imported) return track;  // transients start undefined with nothing before
    const ResourceState& initial = resource.initialState;
    track.layout = initial.layout;
    if ((initial.access & kWriteAccessMask) != 0) {
        track.written = true;
        track.writeStages = initial.stages;
        track.writeAccess = initial.access;
    } else {
        track.readStages = initial.stages;
        track.readAccess = initial.access;
    }
    return track;
}

// Everything a later access has to wait for: the last write and the reads since.
ResourceState pendingState(const Track& track) {
    return {track.writeStages | track.readStages, track.writeAccess, track.layout};
}

// The transients whose memory `resource` takes over: same heap, overlapping bytes, lifetime over.
std::vector<uint32_t> aliasPredecessors(const CompiledGraph& compiled, uint32_t resource) {
    std::vector<uint32_t> predecessors;
    const Placement& placement = compiled.placements[resource];
    if (placement.heap == kInvalidIndex) return predecessors;
    for (uint32_t other : compiled.heaps[placement.heap].residents) {
        const Placement& o = compiled.placements[other];
        const bool sharesBytes =
            placement.offset < o.offset + o.size && o.offset < placement.offset + placement.size;
        if (other != resource && sharesBytes &&
            compiled.lifetimes[other].last < compiled.lifetimes[resource].first)
            predecessors.push_back(other);
    }
    return predecessors;
}

// Applies one access (of a pass, or the required final state) to `track`; returns whether a
// barrier is needed and fills it. `alias` is set on the first use of memory taken over from others.
bool applyAccess(Track& track, const ResourceState& dst, bool writes, ResourceKind kind,
                 const Barrier* alias, Barrier& barrier) {
    const bool layoutChange = kind == ResourceKind::Texture && dst.layout != track.layout;
    bool emit = false;
    if (writes || layoutChange || alias != nullptr) {
        barrier.src = pendingState(track);
        if (alias != nullptr) {
            barrier.src.stages |= alias->src.stages;
            barrier.src.access |= alias->src.access;
            barrier.src.layout = VK_IMAGE_LAYOUT_UNDEFINED;
            barrier.aliasedFrom = alias->aliasedFrom;
        }
        emit = barrier.src.stages != VK_PIPELINE_STAGE_2_NONE || layoutChange || alias != nullptr;
        track.written = true;
        track.writeStages = dst.stages;
        if (writes) {
            track.writeAccess = dst.access & kWriteAccessMask;
            track.readStages = VK_PIPELINE_STAGE_2_NONE;
            track.readAccess = VK_ACCESS_2_NONE;
        } else {
            // A read-only transition acts as a write with no access; the read itself is then synchronised.
            track.writeAccess = VK_ACCESS_2_NONE;
            track.readStages = dst.stages;
            track.readAccess = dst.access;
        }
    } else {
        const bool covered = isSubset(dst.stages, track.readStages) && isSubset(dst.access, track.readAccess);
        if (track.written && !covered) {
            barrier.src = {track.writeStages, track.writeAccess, track.layout};
            emit = true;
        }
        track.readStages |= dst.stages;
        track.readAccess |= dst.access;
    }
    if (kind == ResourceKind::Texture) track.layout = dst.layout;
    barrier.dst = dst;
    if (kind == ResourceKind::Buffer) barrier.src.layout = barrier.dst.layout = VK_IMAGE_LAYOUT_UNDEFINED;
    return emit;
}

}  // namespace

void planBarriers(const GraphDecl& decl, CompiledGraph& compiled) {
    std::vector<Track> tracks;
    tracks.reserve(decl.resources.size());
    for (const ResourceDecl& resource : decl.resources) tracks.push_back(initialTrack(resource));

    compiled.barriers.assign(compiled.order.size(), {});
    for (size_t i = 0; i < compiled.order.size(); ++i) {
        for (const MergedAccess& access : mergeAccesses(decl, decl.passes[compiled.order[i]])) {
            Track& track = tracks[access.resource];
            Barrier alias;
            bool aliased = false;
            if (!track.touched) {
                // Taking over memory: wait for every earlier resident of these bytes.
                for (uint32_t other : aliasPredecessors(compiled, access.resource)) {
                    const ResourceState otherState = pendingState(tracks[other]);
                    alias.src.stages |= otherState.stages;
                    alias.src.access |= otherState.access;
                    // Name the resident used last: the memory's most recent owner.
                    if (!aliased || compiled.lifetimes[other].last > compiled.lifetimes[alias.aliasedFrom].last)
                        alias.aliasedFrom = other;
                    aliased = true;
                }
            }
            Barrier barrier;
            barrier.resource = access.resource;
            const ResourceKind kind = decl.resources[access.resource].kind;
            if (applyAccess(track, access.state, access.writes, kind, aliased ? &alias : nullptr, barrier))
                compiled.barriers[i].push_back(barrier);
            track.touched = true;
            track.last = access.state;
        }
    }

    compiled.finalBarriers.clear();
    compiled.finalStates.assign(decl.resources.size(), ResourceState{});
    for (uint32_t r = 0; r < decl.resources.size(); ++r) {
        const ResourceDecl& resource = decl.resources[r];
        Track& track = tracks[r];
        if (!resource.finalState) {
            compiled.finalStates[r] = track.touched ? track.last
                                      : resource.imported ? resource.initialState
                                                          : ResourceState{};
            continue;
        }
        const ResourceState& required = *resource.finalState;
        compiled.finalStates[r] = required;
        // An unused transient has no memory; an untouched import already in its final state needs nothing.
        if (!resource.imported && !track.touched) continue;
        if (!track.touched && required == resource.initialState) continue;
        Barrier barrier;
        barrier.resource = r;
        const bool writes = (required.access & kWriteAccessMask) != 0;
        if (applyAccess(track, required, writes, resource.kind, nullptr, barrier))
            compiled.finalBarriers.push_back(barrier);
    }
    compiled.steps.emplace_back("barriers");
}

}  // namespace candela::graph::detail
