// Times ScenePose::evaluate — the CPU side of animation: samplers, node world transforms, joint
// matrices, posed bounds — on a glTF file, over many frames at 60 fps steps, with every animation
// of the file playing. No GPU. Prints the median and minimum per frame, with warm caches (evaluate
// after evaluate) and cold ones (32 MiB written between frames, as rendering a frame does in the
// application).
//
//   build/release/tools/bench/candela_pose_bench FILE.glb [frames=4000]

#include "assets/gltf_loader.h"
#include "pose/scene_pose.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

using namespace candela;
using scene::Scene;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: candela_pose_bench FILE [frames]\n");
        return 2;
    }
    const int frames = argc > 2 ? std::max(1, std::atoi(argv[2])) : 4000;
    try {
        const Scene scene = assets::loadGltf(argv[1]);
        const std::vector<std::string> all{"all"};
        pose::ScenePose pose(scene, pose::selectAnimations(scene, all));
        std::vector<uint8_t> flush(size_t(32) << 20);
        const auto run = [&](bool cold) {
            std::vector<double> us;
            for (int f = 0; f < frames; ++f) {
                // One byte per cache line, read and written through the caches (a large fill would
                // use streaming stores that bypass them).
                if (cold)
                    for (size_t i = 0; i < flush.size(); i += 64) flush[i] = uint8_t(flush[i] + 1);
                const auto start = std::chrono::steady_clock::now();
                pose.evaluate(f / 60.0);
                us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
            }
            std::sort(us.begin(), us.end());
            return us;
        };
        const std::vector<double> warm = run(false), cold = run(true);
        size_t channels = 0;
        for (uint32_t a : pose.playing()) channels += scene.animations[a].channels.size();
        std::printf("%s: %zu nodes, %zu channels, %zu skins, %zu animated draws\n", argv[1], scene.nodes.size(), channels,
                    scene.skins.size(), pose.animatedDraws().size());
        std::printf("evaluate over %d frames, warm caches: median %.1f us, min %.1f us\n", frames, warm[warm.size() / 2], warm.front());
        std::printf("evaluate over %d frames, cold caches: median %.1f us, min %.1f us\n", frames, cold[cold.size() / 2], cold.front());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
