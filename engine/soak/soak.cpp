#include "soak/soak.h"

#include "assets/procedural_sky.h"
#include "core/process_memory.h"
#include "vk/context.h"

namespace candela {

std::vector<SoakSample> runSoak(Renderer& renderer, vk::Context& context, RenderSettings settings,
                                const std::vector<assets::Environment>& environments, const SoakSchedule& options,
                                const std::function<void(const SoakSample&)>& onSample) {
    std::vector<SoakSample> samples;
    for (uint32_t frame = 0; frame < options.frames; ++frame) {
        settings.environment = &environments[(frame / std::max(1u, options.switchEvery)) % environments.size()];
        const FrameTiming timing = renderer.renderFrame(settings);
        const uint32_t rendered = frame + 1;
        if (rendered != 1 && rendered % std::max(1u, options.sampleEvery) != 0 && rendered != options.frames) continue;
        // Sample at a quiet point: no frame in flight, so nothing the driver holds for one (on
        // lavapipe, its rasterizer's per-frame blocks come from the C heap) is counted.
        renderer.waitIdle();
        const vk::MemoryStats memory = context.allocator().stats();
        samples.push_back({.frame = rendered,
                           .residentBytes = residentBytes(),
                           .heapBytes = heapInUseBytes(),
                           .heapMappedBytes = heapMappedBytes(),
                           .liveVulkanObjects = context.liveObjects(),
                           .deviceMemoryBytes = memory.deviceMemoryBytes,
                           .liveAllocations = memory.liveAllocations,
                           .lastFrameMs = timing.submitWaitMs});
        if (onSample) onSample(samples.back());
    }
    return samples;
}

std::vector<assets::Environment> soakEnvironments(uint32_t count) {
    std::vector<assets::Environment> environments;
    for (uint32_t i = 0; i < count; ++i) {
        assets::SkyParams params;
        params.sunAzimuthDegrees = 45.0f + 360.0f * float(i) / float(count);
        environments.push_back(assets::makeProceduralSky(params));
    }
    return environments;
}

}  // namespace candela
