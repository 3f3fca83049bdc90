// The tonemap pass against the CPU evaluation of the same shared code (shaders/shared/tonemap.h):
// the procedural HDR pattern (radiance 1/16 … 24) tone mapped by every operator into both an
// 8-bit UNORM target (the shader encodes sRGB) and an _SRGB target (the hardware does).
#include "gpu_test.h"
#include "graph_runner.h"

#include "passes/diagnostics/pattern_pass.h"
#include "passes/post/tonemap_pass.h"
#include "shared/pattern.h"
#include "shared/tonemap.h"

#include <glm/gtc/packing.hpp>

#include <cmath>

namespace candela::test::tonemap_test {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 48;

struct Output {
    std::vector<uint8_t> unorm, srgb;
};

Output render(vk::Context& context, const passes::TonemapSettings& settings) {
    const passes::PatternPass pattern(context);
    passes::TonemapPass tonemap(context);
    GraphRunner runner(context);
    graph::RenderGraph graph;
    const graph::TextureId hdr = pattern.add(graph, kWidth, kHeight, 1.0f);
    const graph::BufferId unormBuffer = runner.readbackBuffer(graph, "unorm", kWidth * kHeight * 4);
    const graph::BufferId srgbBuffer = runner.readbackBuffer(graph, "srgb", kWidth * kHeight * 4);
    for (const auto& [format, buffer] :
         {std::pair{VK_FORMAT_R8G8B8A8_UNORM, unormBuffer}, std::pair{VK_FORMAT_R8G8B8A8_SRGB, srgbBuffer}}) {
        const graph::TextureId target = graph.createTexture("ldr", {.width = kWidth, .height = kHeight, .format = format});
        passes::addReadbackPass(graph, tonemap.add(graph, hdr, target, settings), buffer);
    }
    runner.run(graph);
    return {runner.read<uint8_t>(unormBuffer), runner.read<uint8_t>(srgbBuffer)};
}

// The CPU reference: the pattern in half precision (the HDR target is RGBA16F), tone mapped and
// encoded by the same shared functions.
glm::vec3 expected(uint32_t x, uint32_t y, const passes::TonemapSettings& settings) {
    const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / glm::vec2(kWidth, kHeight);
    glm::vec3 radiance = shading::patternRadiance(uv);
    for (int c = 0; c < 3; ++c) radiance[c] = glm::unpackHalf1x16(glm::packHalf1x16(radiance[c]));
    return shading::srgbEncode(shading::applyTonemap(radiance * std::exp2(settings.exposureEv), uint32_t(settings.op)));
}

// Metric: max abs difference per 8-bit channel over all pixels ≤ 1 level, for both targets.
TEST_F(GpuTest, TonemapMatchesCpuReferenceForEveryOperatorAndBothTargetKinds) {
    for (options::Tonemap op : {options::Tonemap::PbrNeutral, options::Tonemap::Aces, options::Tonemap::Agx,
                               options::Tonemap::Reinhard, options::Tonemap::Linear}) {
        const passes::TonemapSettings settings{.exposureEv = -1.0f, .op = op, .background = glm::vec3(0.0f)};
        const Output out = render(context(), settings);
        ASSERT_EQ(out.unorm.size(), size_t(kWidth) * kHeight * 4);
        int maxUnorm = 0, maxSrgb = 0;
        for (uint32_t y = 0; y < kHeight; ++y)
            for (uint32_t x = 0; x < kWidth; ++x) {
                const glm::vec3 e = expected(x, y, settings);
                for (int c = 0; c < 3; ++c) {
                    const int level = static_cast<int>(std::lround(e[c] * 255.0f));
                    const size_t i = (size_t(y) * kWidth + x) * 4 + c;
                    maxUnorm = std::max(maxUnorm, std::abs(level - out.unorm[i]));
                    maxSrgb = std::max(maxSrgb, std::abs(level - out.srgb[i]));
                }
            }
        EXPECT_LE(maxUnorm, 1) << options::tonemapName(op) << " (UNORM target, shader sRGB encode)";
        EXPECT_LE(maxSrgb, 1) << options::tonemapName(op) << " (_SRGB target, hardware encode)";
    }
}

TEST_F(GpuTest, TonemapDitherStaysWithinOneLevel) {
    const Output plain = render(context(), {.op = options::Tonemap::PbrNeutral});
    const Output dithered = render(context(), {.op = options::Tonemap::PbrNeutral, .dither = true});
    int maxDifference = 0;
    size_t changed = 0;
    for (size_t i = 0; i < plain.unorm.size(); ++i) {
        maxDifference = std::max(maxDifference, std::abs(int(plain.unorm[i]) - int(dithered.unorm[i])));
        changed += plain.unorm[i] != dithered.unorm[i];
    }
    EXPECT_LE(maxDifference, 1);
    EXPECT_GT(changed, plain.unorm.size() / 10);  // the noise really is there
}

}  // namespace
}  // namespace candela::test::tonemap_test
