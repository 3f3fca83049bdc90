#include "vk/swapchain.h"

#include "vk/check.h"
#include "vk/commands.h"
#include "vk/context.h"

#include <algorithm>
#include <string>

namespace candela::vk {

namespace {

// The tonemap pass encodes sRGB itself (and dithers), and ImGui's colours are meant for a UNORM
// target: prefer an 8-bit UNORM format in the sRGB colour space.
VkSurfaceFormatKHR chooseFormat(const std::vector<VkSurfaceFormatKHR>& formats) {
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_A2B10G10R10_UNORM_PACK32})
        for (const VkSurfaceFormatKHR& f : formats)
            if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    return formats.front();
}

}  // namespace

Swapchain::Swapchain(Context& context, VkSurfaceKHR surface, bool vsync)
    : mContext(context), mSurface(surface), mVsync(vsync) {
    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(context.physicalDevice(), surface, &count, nullptr));
    mModes.resize(count);
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(context.physicalDevice(), surface, &count, mModes.data()));
    mSpareAcquire = createSemaphore(context);
}

Swapchain::~Swapchain() {
    try {
        mContext.waitIdleAndCollect();
    } catch (...) {
        // Device lost while closing: destroy what we own anyway.
    }
    destroyImages();
    mSpareAcquire.reset();
    mContext.waitIdleAndCollect();
    if (mSwapchain) vkDestroySwapchainKHR(mContext.device(), mSwapchain, nullptr);
    vkDestroySurfaceKHR(mContext.instance(), mSurface, nullptr);
}

VkPresentModeKHR Swapchain::choosePresentMode() const {
    if (mVsync) return VK_PRESENT_MODE_FIFO_KHR;  // always supported
    for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
        if (std::find(mModes.begin(), mModes.end(), wanted) != mModes.end()) return wanted;
    return VK_PRESENT_MODE_FIFO_KHR;
}

void Swapchain::setVsync(bool vsync) { mVsync = vsync; }

void Swapchain::destroyImages() {
    for (PerImage& image : mImages) {
        image.view.reset();
        image.acquired.reset();
        image.rendered.reset();
    }
    mImages.clear();
}

bool Swapchain::recreate(VkExtent2D framebufferSize) {
    VkPhysicalDevice gpu = mContext.physicalDevice();
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu, mSurface, &caps));
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == 0xFFFFFFFFu) {  // the surface size follows the swapchain's
        extent.width = std::clamp(framebufferSize.width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent.height = std::clamp(framebufferSize.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    if (extent.width == 0 || extent.height == 0 || framebufferSize.width == 0 || framebufferSize.height == 0)
        return false;  // minimized: keep the old swapchain (if any) until there is something to show

    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, mSurface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, mSurface, &count, formats.data()));
    if (formats.empty()) throw VulkanError("the window surface offers no formats", VK_ERROR_FORMAT_NOT_SUPPORTED);

    mFormat = chooseFormat(formats);
    mPresentMode = choosePresentMode();
    mUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    mMinImageCount = std::max(caps.minImageCount + 1, 3u);
    if (caps.maxImageCount > 0) mMinImageCount = std::min(mMinImageCount, caps.maxImageCount);

    // The old images may still be in use by frames in flight or the presentation engine.
    VK_CHECK(vkDeviceWaitIdle(mContext.device()));
    VkSwapchainKHR old = mSwapchain;
    const VkSwapchainCreateInfoKHR info{
        .sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
        .surface = mSurface,
        .minImageCount = mMinImageCount,
        .imageFormat = mFormat.format,
        .imageColorSpace = mFormat.colorSpace,
        .imageExtent = extent,
        .imageArrayLayers = 1,
        .imageUsage = mUsage,
        .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,
        .preTransform = (caps.supportedTransforms & VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR)
                            ? VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR
                            : caps.currentTransform,
        .compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : static_cast<VkCompositeAlphaFlagBitsKHR>(caps.supportedCompositeAlpha &
                                                                        -caps.supportedCompositeAlpha),
        .presentMode = mPresentMode,
        .clipped = VK_TRUE,
        .oldSwapchain = old};
    VkSwapchainKHR created = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSwapchainKHR(mContext.device(), &info, nullptr, &created));
    destroyImages();
    mContext.waitIdleAndCollect();
    if (old) vkDestroySwapchainKHR(mContext.device(), old, nullptr);
    mSwapchain = created;
    mExtent = extent;
    ++mRecreations;

    VK_CHECK(vkGetSwapchainImagesKHR(mContext.device(), mSwapchain, &count, nullptr));
    std::vector<VkImage> images(count);
    VK_CHECK(vkGetSwapchainImagesKHR(mContext.device(), mSwapchain, &count, images.data()));
    mImages.resize(count);
    for (uint32_t i = 0; i < count; ++i) {
        PerImage& image = mImages[i];
        image.image = images[i];
        const VkImageViewCreateInfo viewInfo{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                             .image = images[i],
                                             .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                             .format = mFormat.format,
                                             .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
        VkImageView view = VK_NULL_HANDLE;
        VK_CHECK(vkCreateImageView(mContext.device(), &viewInfo, nullptr, &view));
        image.view = ImageViewHandle(mContext, view);
        image.acquired = createSemaphore(mContext);
        image.rendered = createSemaphore(mContext);
        const std::string name = "swapchain image " + std::to_string(i);
        mContext.setName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(images[i]), name.c_str());
    }
    return true;
}

std::optional<SwapchainImage> Swapchain::acquire() {
    uint32_t index = 0;
    const VkResult result = vkAcquireNextImageKHR(mContext.device(), mSwapchain, UINT64_MAX,
                                                  mSpareAcquire.get(), VK_NULL_HANDLE, &index);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) return std::nullopt;
    if (result != VK_SUBOPTIMAL_KHR) VK_CHECK(result);
    PerImage& image = mImages[index];
    std::swap(image.acquired, mSpareAcquire);
    // A suboptimal image has its semaphore signalled: render and present it, then recreate.
    return SwapchainImage{index, image.image, image.view.get(), image.acquired.get(), image.rendered.get()};
}

bool Swapchain::present(const SwapchainImage& image) {
    const VkSemaphore wait = image.rendered;
    const VkPresentInfoKHR info{.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
                                .waitSemaphoreCount = 1,
                                .pWaitSemaphores = &wait,
                                .swapchainCount = 1,
                                .pSwapchains = &mSwapchain,
                                .pImageIndices = &image.index};
    const VkResult result = vkQueuePresentKHR(mContext.graphicsQueue().queue, &info);
    if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return false;
    VK_CHECK(result);
    return true;
}

}  // namespace candela::vk
