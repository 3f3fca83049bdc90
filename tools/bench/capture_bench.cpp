// Times a headless capture (render + readback) of the foundation's frame graph at a given size:
// CPU wall time of submit+wait, CPU time to copy the pixels out, and GPU time per pass.
// The first frame (pipeline and transient creation) is reported separately; the rest are medians.
//
//   build/release/tools/bench/candela_capture_bench [width=1920] [height=1080] [frames=20]

#include "render/renderer.h"
#include "vk/context.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    using namespace candela;
    const uint32_t width = argc > 1 ? static_cast<uint32_t>(std::atoi(argv[1])) : 1920;
    const uint32_t height = argc > 2 ? static_cast<uint32_t>(std::atoi(argv[2])) : 1080;
    const int frames = argc > 3 ? std::atoi(argv[3]) : 20;
    vk::Context context({});
    Renderer renderer(context);
    const auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    };
    std::printf("device: %s\n", context.report().name.c_str());
    for (bool floatOutput : {false, true}) {
        const RenderSettings settings{.width = width, .height = height, .floatOutput = floatOutput};
        const auto first0 = std::chrono::steady_clock::now();
        renderer.capture(settings);
        const double firstMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - first0).count();
        std::vector<double> total, submitWait, readback;
        std::map<std::string, std::vector<double>> passes;
        for (int i = 0; i < frames; ++i) {
            const auto t0 = std::chrono::steady_clock::now();
            const CapturedFrame frame = renderer.capture(settings);
            total.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
            submitWait.push_back(frame.submitWaitMs);
            readback.push_back(frame.readbackMs);
            const auto& decl = renderer.lastGraph().declaration();
            for (uint32_t p : renderer.lastGraph().compiled().order) passes[decl.passes[p].name].push_back(frame.timings.gpuMs[p]);
        }
        std::printf("%ux%u %s: first frame %.1f ms; median of %d: capture %.2f ms (submit+wait %.2f, readback copy %.2f);",
                    width, height, floatOutput ? "float (RGBA16F readback)" : "png (RGBA8 sRGB)", firstMs, frames,
                    median(total), median(submitWait), median(readback));
        for (const auto& [name, ms] : passes) std::printf(" %s %.2f ms GPU;", name.c_str(), median(ms));
        std::printf("\n");
    }
    return 0;
}
