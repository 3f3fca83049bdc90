#include "vk/swapchain.h"

#include "core/errors.h"
#include "vk/check.h"
#include "vk/commands.h"
#include "vk/context.h"
#include "vk/swapchain_choices.h"

#include <algorithm>
#include <string>

namespace candela::vk {

Swapchain::Swapchain(Context& context, VkSurfaceKHR surface, bool vsync)
    : mContext(context), mSurface(surface), mVsync(vsync) {
    // The device was chosen before the surface existed, by the window system's per-family check
    // (ContextDesc::presentSupport); now ask about this very surface. On failure the surface is
    // destroyed here (no destructor runs for a constructor that throws).
    try {
        std::vector<bool> support;
        uint32_t families = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &families, nullptr);
        for (uint32_t family = 0; family < families; ++family) {
            VkBool32 supported = VK_FALSE;
            VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(context.physicalDevice(), family, surface, &supported));
            support.push_back(supported == VK_TRUE);
        }
        if (std::string problem = presentSupportProblem(support, context.graphicsQueue().family, context.properties().deviceName);
            !problem.empty())
            throw UserError(problem);
    } catch (...) {
        vkDestroySurfaceKHR(context.instance(), surface, nullptr);
        throw;
    }
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

VkExtent2D Swapchain::wantedExtent(VkExtent2D framebufferSize) const {
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(mContext.physicalDevice(), mSurface, &caps));
    return chooseSwapchainExtent(caps, framebufferSize);
}

bool Swapchain::recreate(VkExtent2D framebufferSize) {
    VkPhysicalDevice gpu = mContext.physicalDevice();
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu, mSurface, &caps));
    const VkExtent2D extent = chooseSwapchainExtent(caps, framebufferSize);
    if (extent.width == 0 || extent.height == 0 || framebufferSize.width == 0 || framebufferSize.height == 0)
        return false;  // minimized: keep the old swapchain (if any) until there is something to show

    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, mSurface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, mSurface, &count, formats.data()));
    mFormat = chooseSurfaceFormat(formats);
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
