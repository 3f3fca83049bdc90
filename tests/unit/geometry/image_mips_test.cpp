// geometry::boxMipChain (geometry/image_mips.h) on small images: the levels' sizes halve as
// Vulkan's, a constant image stays constant at every level, and a 2 × 2 block averages in linear
// light when the image is sRGB, as it is otherwise. The chain against the exact box average on a
// random image, next to the device's blits: tests/gpu/mip_chain_test.cpp.
#include "geometry/image_mips.h"

#include <gtest/gtest.h>

namespace candela::geometry {
namespace {

scene::Image filledImage(uint32_t width, uint32_t height, std::array<uint8_t, 4> texel, bool srgb) {
    scene::Image image{.name = "filled", .width = width, .height = height, .srgb = srgb};
    for (uint32_t i = 0; i < width * height; ++i) image.rgba8.insert(image.rgba8.end(), texel.begin(), texel.end());
    return image;
}

TEST(ImageMips, LevelsHalveAsVulkansAndAConstantImageStaysConstant) {
    for (const bool srgb : {false, true}) {
        const scene::Image image = filledImage(13, 7, {200, 17, 90, 255}, srgb);
        const std::vector<std::vector<uint8_t>> chain = boxMipChain(image);
        ASSERT_EQ(chain.size(), 3u);  // 6 × 3, 3 × 1, 1 × 1
        const size_t texels[] = {6 * 3, 3 * 1, 1};
        for (size_t m = 0; m < chain.size(); ++m) {
            ASSERT_EQ(chain[m].size(), texels[m] * 4) << m;
            for (size_t i = 0; i < chain[m].size(); i += 4)
                EXPECT_EQ((std::array<uint8_t, 4>{chain[m][i], chain[m][i + 1], chain[m][i + 2], chain[m][i + 3]}),
                          (std::array<uint8_t, 4>{200, 17, 90, 255}))
                    << "level " << m + 1 << (srgb ? " sRGB" : " UNORM");
        }
    }
}

TEST(ImageMips, TwoByTwoAveragesInLinearLightForSrgbAndRoundsTiesToEven) {
    scene::Image image{.name = "block", .width = 2, .height = 2};
    // Columns 0 and 255 in RGB; alpha 0, 1, 2, 3 → 1.5 → 2 (ties to even).
    image.rgba8 = {0, 0, 0, 0, 255, 255, 255, 1, 0, 0, 0, 2, 255, 255, 255, 3};
    std::vector<std::vector<uint8_t>> chain = boxMipChain(image);
    ASSERT_EQ(chain.size(), 1u);
    EXPECT_EQ(chain[0], (std::vector<uint8_t>{128, 128, 128, 2}));  // 127.5 → 128 (even)
    image.srgb = true;
    chain = boxMipChain(image);
    // Linear 0.5 is sRGB code 187.5 → 188; alpha stays linear.
    EXPECT_EQ(chain[0], (std::vector<uint8_t>{188, 188, 188, 2}));
}

}  // namespace
}  // namespace candela::geometry
