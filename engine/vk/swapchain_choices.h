#pragma once
// The swapchain's decisions as pure functions (unit-tested with the surface reports of real
// devices, no window): which surface format to present in — only formats the screenshot path can
// convert, so the two always agree —, that conversion, the image extent, when to recreate, and
// whether the chosen queue can present to the window's surface.
//
// Pure: no Vulkan calls.

#include <vulkan/vulkan_core.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace candela::vk {

// The formats Candela presents in, preferred first: 8-bit UNORM (the tonemap pass encodes sRGB
// itself and dithers; ImGui's colours are meant for a UNORM target), then 10-bit UNORM. Each in
// the sRGB nonlinear colour space. presentTexelsToRgba8 converts every one of them.
inline constexpr VkFormat kPresentFormats[] = {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM,
                                               VK_FORMAT_A2B10G10R10_UNORM_PACK32, VK_FORMAT_A2R10G10B10_UNORM_PACK32};

// The first of kPresentFormats that `offered` (vkGetPhysicalDeviceSurfaceFormatsKHR) has in
// VK_COLOR_SPACE_SRGB_NONLINEAR_KHR; a lone VK_FORMAT_UNDEFINED entry (any format) gives the first.
// Throws UserError (one line, listing what the surface offers) when there is none.
VkSurfaceFormatKHR chooseSurfaceFormat(std::span<const VkSurfaceFormatKHR> offered);

// `texels` texels of a swapchain image in `format` (4 bytes each, as copied to a buffer) as RGBA8.
// Throws InternalError for a format outside kPresentFormats.
std::vector<uint8_t> presentTexelsToRgba8(VkFormat format, const std::byte* data, size_t texels);

// The size of the swapchain's images: the surface's currentExtent, or, where the surface lets the
// application choose (currentExtent 0xFFFFFFFF), the window's framebuffer size clamped to the
// surface's range.
VkExtent2D chooseSwapchainExtent(const VkSurfaceCapabilitiesKHR& surface, VkExtent2D framebufferSize);

// What decides whether the viewer recreates its swapchain before a frame.
struct SwapchainStatus {
    bool valid = false;               // it has images
    bool outOfDate = false;           // acquire or present returned OUT_OF_DATE or SUBOPTIMAL
    bool presentModeChanged = false;  // vsync was toggled
    VkExtent2D extent{};              // its images' size
};
// Recreate when there is no swapchain, the presentation engine said so, vsync changed, or the
// extent a swapchain made now would have (`wanted`: chooseSwapchainExtent of the surface's
// capabilities now and the window's framebuffer size) is not the swapchain's. Never because the
// window's framebuffer size and the surface's extent disagree — they may for good (a surface
// clamped to its range, a compositor that scales) and recreating would not change it, every frame.
bool swapchainNeedsRecreate(const SwapchainStatus& status, VkExtent2D wanted);

// "" when queue family `family` of the device can present to the window's surface
// (`familySupport[i]`: vkGetPhysicalDeviceSurfaceSupportKHR for family i); else a one-line
// message naming the device, the family and the families that can present.
std::string presentSupportProblem(const std::vector<bool>& familySupport, uint32_t family, const std::string& deviceName);

}  // namespace candela::vk
