// The swapchain's pure decisions (vk/swapchain_choices.h): the surface format, chosen from the
// format lists real surfaces report, always one the screenshot conversion handles; that conversion;
// the extent; recreation only when something changed; the present-support check on the surface.
#include "vk/swapchain_choices.h"

#include "core/errors.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

namespace candela::vk {
namespace {

constexpr VkColorSpaceKHR kSrgb = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;

// Surface format lists as drivers report them (vkGetPhysicalDeviceSurfaceFormatsKHR).
const std::vector<VkSurfaceFormatKHR> kMesaX11 = {{VK_FORMAT_B8G8R8A8_SRGB, kSrgb}, {VK_FORMAT_B8G8R8A8_UNORM, kSrgb}};
const std::vector<VkSurfaceFormatKHR> kMesaX11Depth30 = {{VK_FORMAT_A2R10G10B10_UNORM_PACK32, kSrgb}};
const std::vector<VkSurfaceFormatKHR> kNvidiaWindowsHdr = {
    {VK_FORMAT_B8G8R8A8_UNORM, kSrgb}, {VK_FORMAT_B8G8R8A8_SRGB, kSrgb}, {VK_FORMAT_A2B10G10R10_UNORM_PACK32, kSrgb},
    {VK_FORMAT_A2B10G10R10_UNORM_PACK32, VK_COLOR_SPACE_HDR10_ST2084_EXT},
    {VK_FORMAT_R16G16B16A16_SFLOAT, VK_COLOR_SPACE_EXTENDED_SRGB_LINEAR_EXT}};
const std::vector<VkSurfaceFormatKHR> kAndroid = {{VK_FORMAT_R8G8B8A8_UNORM, kSrgb},
                                                  {VK_FORMAT_R8G8B8A8_SRGB, kSrgb},
                                                  {VK_FORMAT_R5G6B5_UNORM_PACK16, kSrgb},
                                                  {VK_FORMAT_A2B10G10R10_UNORM_PACK32, kSrgb}};
const std::vector<VkSurfaceFormatKHR> kMoltenVk = {{VK_FORMAT_B8G8R8A8_UNORM, kSrgb},
                                                   {VK_FORMAT_B8G8R8A8_SRGB, kSrgb},
                                                   {VK_FORMAT_R16G16B16A16_SFLOAT, kSrgb},
                                                   {VK_FORMAT_A2B10G10R10_UNORM_PACK32, kSrgb},
                                                   {VK_FORMAT_B8G8R8A8_UNORM, VK_COLOR_SPACE_DISPLAY_P3_NONLINEAR_EXT}};

TEST(SwapchainChoices, FormatFromRealSurfaces) {
    EXPECT_EQ(chooseSurfaceFormat(kMesaX11).format, VK_FORMAT_B8G8R8A8_UNORM);
    EXPECT_EQ(chooseSurfaceFormat(kMesaX11Depth30).format, VK_FORMAT_A2R10G10B10_UNORM_PACK32);
    EXPECT_EQ(chooseSurfaceFormat(kNvidiaWindowsHdr).format, VK_FORMAT_B8G8R8A8_UNORM);
    EXPECT_EQ(chooseSurfaceFormat(kAndroid).format, VK_FORMAT_R8G8B8A8_UNORM);
    EXPECT_EQ(chooseSurfaceFormat(kMoltenVk).format, VK_FORMAT_B8G8R8A8_UNORM);
    // "Any format".
    const std::vector<VkSurfaceFormatKHR> any = {{VK_FORMAT_UNDEFINED, kSrgb}};
    EXPECT_EQ(chooseSurfaceFormat(any).format, VK_FORMAT_B8G8R8A8_UNORM);
    // Every choice converts for screenshots.
    for (const auto* list : {&kMesaX11, &kMesaX11Depth30, &kNvidiaWindowsHdr, &kAndroid, &kMoltenVk, &any}) {
        const VkSurfaceFormatKHR chosen = chooseSurfaceFormat(*list);
        EXPECT_EQ(chosen.colorSpace, kSrgb);
        const std::byte texel[4] = {};
        EXPECT_NO_THROW(presentTexelsToRgba8(chosen.format, texel, 1));
    }
}

TEST(SwapchainChoices, NoUsableFormatIsAOneLineError) {
    const std::vector<VkSurfaceFormatKHR> hdrOnly = {{VK_FORMAT_A2B10G10R10_UNORM_PACK32, VK_COLOR_SPACE_HDR10_ST2084_EXT},
                                                     {VK_FORMAT_R5G6B5_UNORM_PACK16, kSrgb}};
    for (const std::vector<VkSurfaceFormatKHR>& list : {hdrOnly, std::vector<VkSurfaceFormatKHR>{}}) {
        try {
            chooseSurfaceFormat(list);
            FAIL() << "no error";
        } catch (const UserError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("no format Candela can present"), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos);
            if (!list.empty()) {
                EXPECT_NE(message.find("R5G6B5_UNORM_PACK16"), std::string::npos) << message;
            }
        }
    }
}

TEST(SwapchainChoices, ScreenshotConversionOfEveryPresentFormat) {
    const std::byte rgba[4] = {std::byte{10}, std::byte{20}, std::byte{30}, std::byte{255}};
    EXPECT_EQ(presentTexelsToRgba8(VK_FORMAT_R8G8B8A8_UNORM, rgba, 1), (std::vector<uint8_t>{10, 20, 30, 255}));
    EXPECT_EQ(presentTexelsToRgba8(VK_FORMAT_B8G8R8A8_UNORM, rgba, 1), (std::vector<uint8_t>{30, 20, 10, 255}));
    // 10-bit channels: red 1023, green 512, blue 0, alpha 3 (A2B10G10R10: red in the low bits).
    const uint32_t word = 1023u | (512u << 10) | (0u << 20) | (3u << 30);
    std::byte packed[4];
    std::memcpy(packed, &word, 4);
    EXPECT_EQ(presentTexelsToRgba8(VK_FORMAT_A2B10G10R10_UNORM_PACK32, packed, 1), (std::vector<uint8_t>{255, 128, 0, 255}));
    EXPECT_EQ(presentTexelsToRgba8(VK_FORMAT_A2R10G10B10_UNORM_PACK32, packed, 1), (std::vector<uint8_t>{0, 128, 255, 255}));
    for (VkFormat format : kPresentFormats) EXPECT_NO_THROW(presentTexelsToRgba8(format, packed, 1));
    EXPECT_THROW(presentTexelsToRgba8(VK_FORMAT_R16G16B16A16_SFLOAT, packed, 1), InternalError);
}

VkSurfaceCapabilitiesKHR surface(uint32_t width, uint32_t height) {
    VkSurfaceCapabilitiesKHR caps{};
    caps.currentExtent = {width, height};
    caps.minImageExtent = {1, 1};
    caps.maxImageExtent = {4096, 4096};
    return caps;
}

TEST(SwapchainChoices, ExtentFollowsTheSurfaceOrTheFramebuffer) {
    EXPECT_EQ(chooseSwapchainExtent(surface(800, 600), {801, 600}).width, 800u);
    EXPECT_EQ(chooseSwapchainExtent(surface(0xFFFFFFFFu, 0xFFFFFFFFu), {801, 600}).width, 801u);
    EXPECT_EQ(chooseSwapchainExtent(surface(0xFFFFFFFFu, 0xFFFFFFFFu), {9000, 600}).width, 4096u);
}

TEST(SwapchainChoices, RecreatedOnceWhenTheWindowAndTheSurfaceDisagree) {
    // The window's framebuffer is 801 wide, the surface says 800 (and keeps saying it).
    const VkExtent2D framebuffer{801, 600};
    SwapchainStatus status{.valid = false};
    int recreations = 0;
    for (int frame = 0; frame < 10; ++frame) {
        const VkExtent2D wanted = chooseSwapchainExtent(surface(800, 600), framebuffer);
        if (swapchainNeedsRecreate(status, wanted)) {
            ++recreations;
            status = {.valid = true, .extent = wanted};
        }
    }
    EXPECT_EQ(recreations, 1);
    // A real change, an out-of-date report or a vsync toggle each recreate.
    EXPECT_TRUE(swapchainNeedsRecreate(status, chooseSwapchainExtent(surface(640, 600), framebuffer)));
    EXPECT_TRUE(swapchainNeedsRecreate({.valid = true, .outOfDate = true, .extent = {800, 600}}, {800, 600}));
    EXPECT_TRUE(swapchainNeedsRecreate({.valid = true, .presentModeChanged = true, .extent = {800, 600}}, {800, 600}));
    EXPECT_FALSE(swapchainNeedsRecreate({.valid = true, .extent = {800, 600}}, {800, 600}));
}

TEST(SwapchainChoices, PresentSupportOnTheSurface) {
    EXPECT_EQ(presentSupportProblem({true}, 0, "llvmpipe"), "");
    EXPECT_EQ(presentSupportProblem({true, false, true}, 2, "GPU"), "");
    // A hybrid laptop's discrete GPU that does not drive the display: no family can present.
    const std::string none = presentSupportProblem({false, false, false}, 0, "NVIDIA GeForce RTX 3060 Laptop GPU");
    EXPECT_NE(none.find("NVIDIA GeForce RTX 3060 Laptop GPU's queue family 0"), std::string::npos) << none;
    EXPECT_NE(none.find("families that can: none"), std::string::npos) << none;
    EXPECT_NE(none.find("--device"), std::string::npos) << none;
    EXPECT_NE(presentSupportProblem({false, true}, 0, "GPU").find("families that can: 1"), std::string::npos);
}

}  // namespace
}  // namespace candela::vk
