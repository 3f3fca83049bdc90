// geometry::boxMipChain (geometry/image_mips.h) on small images: the levels' sizes halve as
// Vulkan's, a constant image stays constant at every level, and a 2 × 2 block averages in linear
// light when the image is sRGB, as it is otherwise; both chains write the same texels into rows
// with padding between them, keep the texels pinned for a seeded image, and refuse views of the
// wrong levels. The chain against the exact box average on a
// random image, next to the device's blits: tests/gpu/mip_chain_test.cpp.
#include "core/cache_files.h"
#include "geometry/image_mips.h"
#include "geometry/normal_map_mips.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>

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

// Levels written into another owner's memory, rows further apart than their texels (a linearly tiled
// texture's): the same texels as the packed chain, and the padding between rows left alone.
TEST(ImageMips, ChainsWrittenIntoPaddedRowsMatchThePackedOnes) {
    std::mt19937 random(3);
    scene::Image image{.name = "random", .width = 37, .height = 11};
    image.rgba8.resize(size_t(image.width) * image.height * 4);
    for (uint8_t& b : image.rgba8) b = uint8_t(random());
    constexpr uint8_t kPad = 0xA5;
    for (const bool normalMap : {false, true}) {
        image.srgb = !normalMap;
        const uint32_t first = normalMap ? 0 : 1;
        std::vector<std::vector<uint8_t>> memory;
        std::vector<TexelLevel> levels;
        for (uint32_t level = first; level < mipLevelCount(image.width, image.height); ++level) {
            const uint32_t w = std::max(1u, image.width >> level), h = std::max(1u, image.height >> level);
            const size_t pitch = size_t(w) * 4 + 12;
            memory.emplace_back(pitch * h, kPad);
            levels.push_back({memory.back().data(), pitch, w, h});
        }
        normalMap ? writeNormalMapMipChain(image, levels) : writeBoxMipChain(image, levels);
        const std::vector<std::vector<uint8_t>> packed = normalMap ? normalMapMipChain(image) : boxMipChain(image);
        ASSERT_EQ(packed.size(), levels.size());
        for (size_t i = 0; i < levels.size(); ++i)
            for (uint32_t y = 0; y < levels[i].height; ++y) {
                const uint8_t* row = levels[i].row(y);
                EXPECT_TRUE(std::equal(row, row + levels[i].width * 4, packed[i].begin() + size_t(y) * levels[i].width * 4))
                    << (normalMap ? "normal map" : "box") << " level " << i + first << " row " << y;
                EXPECT_TRUE(std::all_of(row + levels[i].width * 4, row + levels[i].rowPitch, [](uint8_t b) { return b == kPad; }));
            }
    }
}

// The chains' exact texels, pinned: FNV-1a 64 of every level of seeded images, as the chains made
// them before they were rewritten for speed (the values come from that code: 61 × 37 from the code
// before the first rewrite, 142 × 72 from the code before the vectors). 61 × 37 starts with odd sizes
// (filtered levels, then halved ones); 142 × 72 halves exactly down to 71 × 36, rows whose length is
// not a multiple of the vectors' four texels. A change that moves a texel changes images: look at
// them, then update these.
TEST(ImageMips, ChainsOfASeededImageKeepTheirTexels) {
    struct Pinned {
        uint32_t width, height;
        uint64_t unorm, normalMap, srgb;
    };
    for (const Pinned& pinned : {Pinned{61, 37, 0x7e39495230bd7227ull, 0xacbb5b401b467cf1ull, 0xa8618a1384004061ull},
                                 Pinned{142, 72, 0xb0313b0527c539eeull, 0x36313a86f515cc30ull, 0x42e5d9233912d5f8ull}}) {
        SCOPED_TRACE(std::to_string(pinned.width) + " x " + std::to_string(pinned.height));
        std::mt19937 random(5);
        scene::Image image{.name = "seeded", .width = pinned.width, .height = pinned.height};
        image.rgba8.resize(size_t(image.width) * image.height * 4);
        for (uint8_t& b : image.rgba8) b = uint8_t(random() & 255u);
        const auto hash = [](const std::vector<std::vector<uint8_t>>& chain) {
            uint64_t h = kFnv1a64Basis;
            for (const std::vector<uint8_t>& level : chain) h = fnv1a64Update(h, level.data(), level.size());
            return h;
        };
        EXPECT_EQ(hash(boxMipChain(image)), pinned.unorm);
        EXPECT_EQ(hash(normalMapMipChain(image)), pinned.normalMap);
        image.srgb = true;
        EXPECT_EQ(hash(boxMipChain(image)), pinned.srgb);
    }
}

TEST(ImageMips, ViewsOfTheWrongLevelsAreRefused) {
    const scene::Image image = filledImage(8, 4, {1, 2, 3, 4}, false);
    std::vector<std::vector<uint8_t>> memory;
    std::vector<TexelLevel> levels = packedLevels(8, 4, 1, memory);
    EXPECT_THROW(writeBoxMipChain(image, std::span(levels).first(2)), std::invalid_argument);  // one level short
    EXPECT_THROW(writeNormalMapMipChain(image, levels), std::invalid_argument);                 // no level 0
    levels[1].width = 3;
    EXPECT_THROW(writeBoxMipChain(image, levels), std::invalid_argument);  // level 2 is 2 × 1
    levels[1].width = 2;
    levels[1].rowPitch = 4;
    EXPECT_THROW(writeBoxMipChain(image, levels), std::invalid_argument);  // rows overlap
}

}  // namespace
}  // namespace candela::geometry
