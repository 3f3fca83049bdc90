#include "vk/swapchain_choices.h"

#include "core/errors.h"
#include "vk/device_caps.h"

#include <algorithm>
#include <cstring>

namespace candela::vk {
namespace {

std::string surfaceFormatName(VkFormat format) {
    switch (format) {
        case VK_FORMAT_A2R10G10B10_UNORM_PACK32: return "A2R10G10B10_UNORM_PACK32";
        case VK_FORMAT_R16G16B16A16_SFLOAT: return "R16G16B16A16_SFLOAT";
        case VK_FORMAT_R5G6B5_UNORM_PACK16: return "R5G6B5_UNORM_PACK16";
        default: return formatName(format);
    }
}

// 10 bits to 8, rounded.
uint8_t to8(uint32_t ten) { return uint8_t((ten * 255 + 511) / 1023); }

}  // namespace

VkSurfaceFormatKHR chooseSurfaceFormat(std::span<const VkSurfaceFormatKHR> offered) {
    if (offered.size() == 1 && offered[0].format == VK_FORMAT_UNDEFINED)
        return {kPresentFormats[0], VK_COLOR_SPACE_SRGB_NONLINEAR_KHR};
    for (VkFormat wanted : kPresentFormats)
        for (const VkSurfaceFormatKHR& f : offered)
            if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    std::string list;
    for (const VkSurfaceFormatKHR& f : offered)
        list += (list.empty() ? "" : ", ") + surfaceFormatName(f.format) +
                (f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR ? "" : " (colour space " + std::to_string(f.colorSpace) + ")");
    throw UserError("the window surface offers no format Candela can present and screenshot (B8G8R8A8, R8G8B8A8, "
                    "A2B10G10R10 or A2R10G10B10 UNORM in the sRGB colour space); it offers: " +
                    (list.empty() ? std::string("nothing") : list));
}

std::vector<uint8_t> presentTexelsToRgba8(VkFormat format, const std::byte* data, size_t texels) {
    std::vector<uint8_t> out(texels * 4);
    std::memcpy(out.data(), data, out.size());
    switch (format) {
        case VK_FORMAT_R8G8B8A8_UNORM:
        case VK_FORMAT_R8G8B8A8_SRGB: return out;
        case VK_FORMAT_B8G8R8A8_UNORM:
        case VK_FORMAT_B8G8R8A8_SRGB:
            for (size_t i = 0; i < out.size(); i += 4) std::swap(out[i], out[i + 2]);
            return out;
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
        case VK_FORMAT_A2R10G10B10_UNORM_PACK32: {
            const bool bgr = format == VK_FORMAT_A2R10G10B10_UNORM_PACK32;  // R in the high bits
            for (size_t i = 0; i < out.size(); i += 4) {
                uint32_t word;
                std::memcpy(&word, data + i, 4);
                const uint32_t low = word & 1023u, mid = (word >> 10) & 1023u, high = (word >> 20) & 1023u;
                out[i + 0] = to8(bgr ? high : low);
                out[i + 1] = to8(mid);
                out[i + 2] = to8(bgr ? low : high);
                out[i + 3] = uint8_t((word >> 30) * 85u);
            }
            return out;
        }
        default: throw InternalError("presentTexelsToRgba8: no conversion from " + surfaceFormatName(format));
    }
}

VkExtent2D chooseSwapchainExtent(const VkSurfaceCapabilitiesKHR& surface, VkExtent2D framebufferSize) {
    if (surface.currentExtent.width != 0xFFFFFFFFu) return surface.currentExtent;
    return {std::clamp(framebufferSize.width, surface.minImageExtent.width, surface.maxImageExtent.width),
            std::clamp(framebufferSize.height, surface.minImageExtent.height, surface.maxImageExtent.height)};
}

bool swapchainNeedsRecreate(const SwapchainStatus& status, VkExtent2D wanted) {
    return !status.valid || status.outOfDate || status.presentModeChanged || status.extent.width != wanted.width ||
           status.extent.height != wanted.height;
}

std::string presentSupportProblem(const std::vector<bool>& familySupport, uint32_t family, const std::string& deviceName) {
    if (family < familySupport.size() && familySupport[family]) return {};
    std::string can;
    for (size_t i = 0; i < familySupport.size(); ++i)
        if (familySupport[i]) can += (can.empty() ? "" : ", ") + std::to_string(i);
    return "the window's surface cannot be presented to from " + deviceName + "'s queue family " + std::to_string(family) +
           " (families that can: " + (can.empty() ? std::string("none") : can) +
           "); on a hybrid laptop, choose the GPU driving the display with --device";
}

}  // namespace candela::vk
