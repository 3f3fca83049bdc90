#pragma once
// Soak: renders the scene frame after frame, switching the environment every few frames (each
// switch reruns the IBL precompute), and samples host and device memory, so that growth after
// warm-up shows. Used by `candela soak` (the figures in docs/robustness.md) and the soak test.

#include "assets/environment.h"
#include "render/renderer.h"

#include <functional>
#include <vector>

namespace candela {

// How long a soak runs, how often it switches the environment and samples.
struct SoakSchedule {
    uint32_t frames = 10000;
    uint32_t switchEvery = 100;  // frames per environment
    uint32_t sampleEvery = 100;  // frames between samples (and at frame 1)
};

struct SoakSample {
    uint32_t frame = 0;            // frames rendered so far
    uint64_t residentBytes = 0;    // host RSS
    uint64_t heapBytes = 0;        // C heap in live allocations (not the allocator's cache)
    uint64_t heapMappedBytes = 0;  // of which in blocks mapped on their own (large allocations)
    int64_t liveVulkanObjects = 0; // created through the device layer and not destroyed
    uint64_t deviceMemoryBytes = 0;  // held in VkDeviceMemory objects
    uint32_t liveAllocations = 0;
    double lastFrameMs = 0.0;      // submit+wait of the sampled frame
};

// Renders options.frames frames of `settings` (its environment is replaced by environments[k] for
// frames k·switchEvery …, cycling), sampling after frame 1 and every sampleEvery frames, each
// once the GPU is idle; `onSample` sees each sample as it is taken. Preconditions: `environments` is not empty; the renderer's
// context is otherwise idle.
std::vector<SoakSample> runSoak(Renderer& renderer, vk::Context& context, RenderSettings settings,
                                const std::vector<assets::Environment>& environments, const SoakSchedule& options,
                                const std::function<void(const SoakSample&)>& onSample = {});

// Environments for a soak without files: the procedural sky with the sun at `count` azimuths.
std::vector<assets::Environment> soakEnvironments(uint32_t count = 4);

}  // namespace candela
