#pragma once
// Swapchain: the presentable images of a window surface, recreated on resize, on
// VK_ERROR_OUT_OF_DATE_KHR / VK_SUBOPTIMAL_KHR and when vsync is toggled.
//
// Semaphores: each acquire uses a spare semaphore that is then swapped with the acquired image's
// own (the previous acquire of that image has certainly been waited on once the presentation
// engine hands the image back), and each image has its own "rendered" semaphore that the frame's
// submit signals and the present waits on. So no semaphore is reused while still pending,
// whatever the number of frames in flight.
//
// Ownership: the swapchain owns the surface (given at construction), the images' views and the
// semaphores. The device layer knows nothing of windows: the caller creates the surface.

#include "vk/handle.h"

#include <vulkan/vulkan_core.h>

#include <optional>
#include <vector>

namespace candela::vk {

struct SwapchainImage {
    uint32_t index = 0;
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkSemaphore acquired = VK_NULL_HANDLE;  // signalled when the image may be written: wait on it
    VkSemaphore rendered = VK_NULL_HANDLE;  // signal it when the frame is done: present waits on it
};

class Swapchain {
public:
    // Takes ownership of `surface`. Precondition: VK_KHR_swapchain is enabled. Throws UserError
    // (destroying the surface) when the context's graphics queue family cannot present to this
    // surface (vkGetPhysicalDeviceSurfaceSupportKHR; the device was chosen before the surface
    // existed). Creates no images yet.
    Swapchain(Context& context, VkSurfaceKHR surface, bool vsync);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // (Re)creates the images for the surface's current size, or `framebufferSize` where the
    // surface lets the application choose (chooseSwapchainExtent), in chooseSurfaceFormat's format
    // (throws UserError when the surface offers none Candela can present). Waits for the device to be idle first. Returns false,
    // creating nothing, when the size is 0 (a minimized window): there is nothing to render to.
    bool recreate(VkExtent2D framebufferSize);

    // Acquires the next image; nullopt when the swapchain is out of date (recreate, then retry).
    // Precondition: valid().
    std::optional<SwapchainImage> acquire();
    // Presents `image` once its `rendered` semaphore is signalled. Returns false when the
    // swapchain is out of date or suboptimal and should be recreated before the next frame.
    bool present(const SwapchainImage& image);

    // Takes effect at the next recreate() (FIFO when on; else MAILBOX, IMMEDIATE or FIFO).
    void setVsync(bool vsync);
    bool vsync() const { return mVsync; }
    // True when setVsync changed the present mode since the last recreate().
    bool needsRecreate() const { return mPresentMode != choosePresentMode(); }

    bool valid() const { return mSwapchain != VK_NULL_HANDLE; }
    VkFormat format() const { return mFormat.format; }
    VkExtent2D extent() const { return mExtent; }
    // The extent recreate(framebufferSize) would give the images now (chooseSwapchainExtent of
    // the surface's current capabilities): what swapchainNeedsRecreate compares extent() with.
    VkExtent2D wantedExtent(VkExtent2D framebufferSize) const;
    uint32_t imageCount() const { return static_cast<uint32_t>(mImages.size()); }
    uint32_t minImageCount() const { return mMinImageCount; }
    VkPresentModeKHR presentMode() const { return mPresentMode; }
    // Whether images can be copied from (screenshots).
    bool canReadBack() const { return (mUsage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0; }
    uint32_t recreations() const { return mRecreations; }

private:
    VkPresentModeKHR choosePresentMode() const;
    void destroyImages();

    Context& mContext;
    VkSurfaceKHR mSurface = VK_NULL_HANDLE;
    VkSwapchainKHR mSwapchain = VK_NULL_HANDLE;
    bool mVsync = true;
    VkSurfaceFormatKHR mFormat{};
    VkPresentModeKHR mPresentMode = VK_PRESENT_MODE_FIFO_KHR;
    VkImageUsageFlags mUsage = 0;
    VkExtent2D mExtent{};
    uint32_t mMinImageCount = 2;
    uint32_t mRecreations = 0;
    std::vector<VkPresentModeKHR> mModes;
    struct PerImage {
        VkImage image = VK_NULL_HANDLE;
        ImageViewHandle view;
        Semaphore acquired;
        Semaphore rendered;
    };
    std::vector<PerImage> mImages;
    Semaphore mSpareAcquire;
};

}  // namespace candela::vk
