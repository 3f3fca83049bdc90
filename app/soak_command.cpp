// `candela soak`: the default scene rendered frame after frame (headless), the environment switched
// every K frames, with host RSS, live Vulkan objects and device memory sampled as it runs.

#include "commands.h"
#include "session.h"
#include "assets/builtin_scenes.h"
#include "assets/image_file.h"
#include "core/errors.h"
#include "core/progress.h"
#include "soak/soak.h"

#include <cstdio>
#include <fstream>

namespace candela::app {

namespace {

double mib(uint64_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

}  // namespace

int runSoak(const SoakOptions& options) {
    // Written when the run ends (atomically: a killed run leaves no truncated file).
    TextFile csv(options.out);
    if (!options.out.empty()) {
        assets::checkWritable(options.out);
        csv << "frame,rss_bytes,heap_bytes,live_vulkan_objects,device_memory_bytes,live_allocations,frame_ms\n";
    }
    const scene::Scene grid = assets::makeSphereGrid();
    const std::vector<assets::Environment> environments = soakEnvironments();
    Session session(options.common, EnvironmentChoice{EnvironmentChoice::Kind::None});  // soak brings its own skies
    session.start();
    vk::Context& context = session.context();
    Renderer& renderer = session.renderer();
    RenderSettings settings{.width = options.width, .height = options.height, .scene = &grid};
    settings.defaultLights = false;
    std::printf("soak: %u frames at %ux%u, environment switched every %u frames (%zu procedural skies)\n",
                options.frames, options.width, options.height, options.switchEvery, environments.size());
    std::printf("%8s %10s %10s %12s %14s %12s %10s\n", "frame", "RSS MiB", "heap MiB", "Vk objects", "device MiB",
                "allocations", "frame ms");
    Progress progress("soak", options.frames, options.common.quiet);
    const std::vector<SoakSample> samples =
        runSoak(renderer, context, settings, environments,
                {.frames = options.frames, .switchEvery = options.switchEvery, .sampleEvery = options.sampleEvery},
                [&](const SoakSample& s) {
                    progress.clear();
                    std::printf("%8u %10.1f %10.1f %12lld %14.1f %12u %10.2f\n", s.frame, mib(s.residentBytes),
                                mib(s.heapBytes), static_cast<long long>(s.liveVulkanObjects), mib(s.deviceMemoryBytes),
                                s.liveAllocations, s.lastFrameMs);
                    std::fflush(stdout);
                    if (!options.out.empty())
                        csv << s.frame << ',' << s.residentBytes << ',' << s.heapBytes << ',' << s.liveVulkanObjects << ','
                            << s.deviceMemoryBytes << ',' << s.liveAllocations << ',' << s.lastFrameMs << '\n';
                    char detail[64];
                    std::snprintf(detail, sizeof detail, "frames; RSS %.1f MiB, device %.1f MiB", mib(s.residentBytes),
                                  mib(s.deviceMemoryBytes));
                    progress.step(s.frame, detail);
                });
    progress.finish();
    if (!options.out.empty()) csv.commit();
    // Growth after warm-up: from the first sample at or after one full cycle of environments.
    const uint32_t warmUp = options.switchEvery * uint32_t(environments.size());
    const SoakSample* first = nullptr;
    for (const SoakSample& s : samples)
        if (s.frame >= warmUp) {
            first = &s;
            break;
        }
    if (first && first != &samples.back()) {
        const SoakSample& last = samples.back();
        std::printf("after warm-up (frame %u → %u): RSS %+.1f MiB, heap %+.1f MiB, Vulkan objects %+lld, device memory "
                    "%+.1f MiB\n",
                    first->frame, last.frame, mib(last.residentBytes) - mib(first->residentBytes),
                    mib(last.heapBytes) - mib(first->heapBytes),
                    static_cast<long long>(last.liveVulkanObjects - first->liveVulkanObjects),
                    mib(last.deviceMemoryBytes) - mib(first->deviceMemoryBytes));
    }
    return session.exitCode(0);
}

}  // namespace candela::app
