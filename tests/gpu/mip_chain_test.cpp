// A texture's mip chain, as the device's linear blits make it (vk::Uploader with generateMips) and
// as the CPU makes it for CPU devices (geometry/image_mips.h), each level compared with the exact
// 2 × 2 box average of the level above it (the level as that chain made it), in double precision:
// in linear light for sRGB images, as it is for UNORM ones. A chain that rounds correctly is within
// half a code of the exact average at every texel. And the CPU chain written in place into a
// host-written texture reaches the device as written, and renders as the staged one does.
#include "gpu_test.h"

#include "assets/gltf_loader.h"
#include "core/errors.h"
#include "geometry/image_mips.h"
#include "gpu_scene/gpu_scene.h"
#include "render/renderer.h"
#include "vk/buffer.h"
#include "vk/commands.h"
#include "vk/image.h"
#include "vk/upload.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>

namespace candela::test {
namespace {

double srgbToLinear(double code) {
    const double v = code / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
double linearToSrgbCode(double linear) {
    const double v = linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return v * 255.0;
}

// How far `level` (w × h) lies from the exact box average of `above` (2w × 2h), in codes (of the
// encoded value): the largest distance and the mean signed difference.
struct BoxError {
    double largest = 0.0;
    double mean = 0.0;
};
BoxError boxError(const std::vector<uint8_t>& above, const std::vector<uint8_t>& level, uint32_t w, uint32_t h, bool srgb) {
    BoxError out;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c) {
                double sum = 0.0;
                for (uint32_t dy = 0; dy < 2; ++dy)
                    for (uint32_t dx = 0; dx < 2; ++dx) {
                        const uint8_t code = above[((size_t(2 * y + dy) * 2 * w) + 2 * x + dx) * 4 + size_t(c)];
                        sum += srgb && c < 3 ? srgbToLinear(code) : double(code);
                    }
                const double exact = srgb && c < 3 ? linearToSrgbCode(sum / 4.0) : sum / 4.0;
                const double difference = double(level[(size_t(y) * w + x) * 4 + size_t(c)]) - exact;
                out.largest = std::max(out.largest, std::abs(difference));
                out.mean += difference / (double(w) * h * 4);
            }
    return out;
}

class MipChainTest : public GpuTest {
protected:
    // Every level of a `width` × `height` image holding `texels`, with mips made by the device's blits.
    std::vector<std::vector<uint8_t>> blitChain(const std::vector<uint8_t>& texels, uint32_t width, uint32_t height, bool srgb) {
        const uint32_t levels = std::bit_width(std::max(width, height));
        vk::Image image(context(), {.width = width,
                                    .height = height,
                                    .mipLevels = levels,
                                    .format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                                    .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
        vk::Uploader uploader(context());
        uploader.image(image, std::as_bytes(std::span(texels)), 0, 0, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, true);
        uploader.submitAndWait();
        return readLevels(image);
    }

    // Every level of `image` (RGBA8, in TRANSFER_SRC_OPTIMAL), tightly packed, as the device holds it.
    std::vector<std::vector<uint8_t>> readLevels(const vk::Image& image) {
        const uint32_t width = image.desc().width, height = image.desc().height, levels = image.desc().mipLevels;
        vk::Buffer readback(context(), {.size = VkDeviceSize(width) * height * 4 * 2,
                                        .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                        .memory = vk::MemoryUsage::Readback});
        std::vector<VkBufferImageCopy> regions;
        std::vector<size_t> offsets;
        size_t offset = 0;
        for (uint32_t m = 0; m < levels; ++m) {
            const uint32_t w = std::max(1u, width >> m), h = std::max(1u, height >> m);
            regions.push_back({.bufferOffset = offset, .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, m, 0, 1}, .imageExtent = {w, h, 1}});
            offsets.push_back(offset);
            offset += size_t(w) * h * 4;
        }
        vk::OneShotCommands commands(context());
        const VkCommandBuffer cmd = commands.begin();
        vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), uint32_t(regions.size()),
                               regions.data());
        copiesToHostBarrier(cmd);
        commands.submitAndWait();
        readback.invalidate();
        const auto* bytes = reinterpret_cast<const uint8_t*>(readback.mapped());
        std::vector<std::vector<uint8_t>> out;
        for (uint32_t m = 0; m < levels; ++m)
            out.emplace_back(bytes + offsets[m], bytes + offsets[m] + regions[m].imageExtent.width * regions[m].imageExtent.height * 4);
        return out;
    }
};

// The CPU chain rounds each level to the nearest code (ties to even): within half a code of the box
// average and without bias. lavapipe's blits are not: within 1 code, but UNORM levels are half a
// code high on average, so that a 2048² texture's 11 levels drift up by several codes (the CPU
// chain replaces them on CPU devices: docs/textures.md#mip-chains). Any device's blits stay within
// 1 code a level; the mean of the CPU chain's signed errors within 0.05 of a code (over 64 texels
// or more: on fewer it is noise).
TEST_F(MipChainTest, TheCpuChainRoundsTheBoxAverageAndBlitsStayWithinOneCode) {
    constexpr uint32_t kWidth = 64, kHeight = 32;
    std::mt19937 random(7);
    scene::Image image{.name = "random", .width = kWidth, .height = kHeight};
    image.rgba8.resize(size_t(kWidth) * kHeight * 4);
    for (uint8_t& b : image.rgba8) b = uint8_t(random() & 255u);
    for (const bool srgb : {false, true}) {
        image.srgb = srgb;
        const std::vector<std::vector<uint8_t>> blits = blitChain(image.rgba8, kWidth, kHeight, srgb);
        std::vector<std::vector<uint8_t>> cpu = geometry::boxMipChain(image);
        cpu.insert(cpu.begin(), image.rgba8);
        ASSERT_EQ(cpu.size(), blits.size());
        for (size_t m = 1; m < blits.size(); ++m) {
            const uint32_t w = std::max(1u, kWidth >> m), h = std::max(1u, kHeight >> m);
            if (2 * w != std::max(1u, kWidth >> (m - 1)) || 2 * h != std::max(1u, kHeight >> (m - 1))) continue;  // not 2 × 2 → 1
            const BoxError blit = boxError(blits[m - 1], blits[m], w, h, srgb);
            const BoxError host = boxError(cpu[m - 1], cpu[m], w, h, srgb);
            std::printf("%s level %zu: blits %.3f codes at most, %+.3f on average; cpu %.3f, %+.3f\n", srgb ? "sRGB " : "UNORM", m,
                        blit.largest, blit.mean, host.largest, host.mean);
            EXPECT_LE(host.largest, 0.5 + 1e-6) << "cpu, level " << m << (srgb ? " sRGB" : " UNORM");
            if (w * h >= 64) {
                EXPECT_LE(std::abs(host.mean), 0.05) << "cpu, level " << m << (srgb ? " sRGB" : " UNORM");
            }
            EXPECT_LE(blit.largest, 1.0 + 1e-6) << "blits, level " << m << (srgb ? " sRGB" : " UNORM");
        }
    }
}

// A host-written texture (linear tiling, written in place: how textures reach a CPU device,
// DeviceCaps::hostWrittenTextures) holds every level as written, at an odd size whose small levels'
// rows the driver may pad: read back through the device, each level equals the CPU chain.
TEST_F(MipChainTest, HostWrittenLevelsReachTheDeviceAsWritten) {
    if (context().caps().driver == VK_DRIVER_ID_MESA_LLVMPIPE) {
        EXPECT_TRUE(context().caps().hostWrittenTextures);
    }
    if (!context().caps().hostWrittenTextures) GTEST_SKIP() << "this device's textures are not host-written";
    std::mt19937 random(11);
    scene::Image source{.name = "random", .width = 37, .height = 19, .srgb = true};
    source.rgba8.resize(size_t(source.width) * source.height * 4);
    for (uint8_t& b : source.rgba8) b = uint8_t(random() & 255u);
    const uint32_t levels = geometry::mipLevelCount(source.width, source.height);
    vk::Image image(context(), {.width = source.width,
                                .height = source.height,
                                .mipLevels = levels,
                                .format = VK_FORMAT_R8G8B8A8_SRGB,
                                .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                .name = "host-written",
                                .hostWritten = true});
    const std::vector<geometry::TexelLevel> views = gpu_scene::hostWrittenLevels(image);
    for (uint32_t y = 0; y < source.height; ++y)
        std::copy_n(source.rgba8.begin() + ptrdiff_t(y) * source.width * 4, source.width * 4, views[0].row(y));
    geometry::writeBoxMipChain(source, std::span(views).subspan(1));
    vk::Uploader uploader(context());
    uploader.hostWritten(image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    uploader.submitAndWait();

    std::vector<std::vector<uint8_t>> expected = geometry::boxMipChain(source);
    expected.insert(expected.begin(), source.rgba8);
    EXPECT_EQ(readLevels(image), expected);
    // The staging path refuses a host-written image.
    EXPECT_THROW(uploader.image(image, std::as_bytes(std::span(source.rgba8)), 0, 0, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL),
                 InternalError);
}

// The two ways textures reach a CPU device render alike: DamagedHelmet (colour textures, a normal
// map, its chain) drawn with its textures written in place (lavapipe's own caps) and through staging
// copies (a device profile clears the capability, as it does for a GPU). Metric: the 8-bit images are
// byte-identical — the same texels reach the same sampler either way.
TEST_F(MipChainTest, HostWrittenAndStagedTexturesRenderTheSame) {
    if (!context().caps().hostWrittenTextures) GTEST_SKIP() << "this device's textures are not host-written";
    const std::filesystem::path path = sharedAssets() / "models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared asset missing";
    const scene::Scene scene = assets::loadGltf(path);
    const auto render = [&](vk::Context& device) {
        Renderer renderer(device);
        return renderer.capture({.width = 96, .height = 64, .scene = &scene}).rgba8;
    };
    const std::vector<uint8_t> inPlace = render(context());
    vk::Context staged(vk::ContextDesc{.validation = true, .profile = options::DeviceProfile::Desktop});
    ASSERT_FALSE(staged.caps().hostWrittenTextures);
    const std::vector<uint8_t> copied = render(staged);
    ASSERT_EQ(inPlace.size(), copied.size());
    EXPECT_TRUE(inPlace == copied);
}

}  // namespace
}  // namespace candela::test
