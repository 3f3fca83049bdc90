// Renders a glTF file to a 512×512 PNG through Candela's public API, with `candela render`'s
// defaults (the built-in sky lights it), and prints how long it took.
//   embed_candela MODEL.glb OUT.png

#include <candela/candela.h>

#include <chrono>
#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s MODEL.glb OUT.png\n", argv[0]);
        return 2;
    }
    const auto start = std::chrono::steady_clock::now();
    try {
        candela::Device device;                                        // the best device there is
        const candela::Scene scene = candela::Scene::fromFile(argv[1]);
        const candela::Environment sky = candela::Environment::sky();  // candela render's default
        candela::RenderOptions options;
        options.width = 512;
        options.height = 512;
        const candela::Image image = device.render(scene, options, &sky);
        candela::writeImage(argv[2], image);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("candela %s on %s: wrote %s (%ux%u) in %.2f s\n", candela::version(), device.name().c_str(), argv[2],
                    image.width, image.height, seconds);
        return 0;
    } catch (const candela::InputError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());  // "FILE: REASON"
        return 2;
    } catch (const candela::Error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
