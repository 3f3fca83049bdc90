#pragma once
// Move-only RAII image with its default view (all mips and layers; a cube view for cube maps;
// none for transfer-only images),
// plus ImageView (a Handle) for views of single mips or layers. Destruction is deferred through the context.

#include "vk/handle.h"
#include "vk/memory.h"

#include <vulkan/vulkan_core.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace candela::vk {

class Context;

struct ImageDesc {
    uint32_t width = 1;
    uint32_t height = 1;
    uint32_t depth = 1;
    uint32_t mipLevels = 1;
    uint32_t arrayLayers = 1;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageUsageFlags usage = 0;
    bool cube = false;  // arrayLayers must be a multiple of 6
    MemoryUsage memory = MemoryUsage::GpuOnly;
    const char* name = nullptr;
    uint32_t samples = 1;  // a power of two; > 1: a multisampled attachment (one mip, one layer)
    // Linearly tiled in host-visible, coherent memory (MemoryUsage::Stream, whatever `memory` says),
    // created PREINITIALIZED: the host writes its texels in place (Image::hostTexels), then
    // Uploader::hostWritten moves it to its layout. No staging copy: for devices whose images are
    // host memory anyway (DeviceCaps::hostWrittenTextures says where it may be used).
    bool hostWritten = false;

    // e.g. ImageDesc::renderTarget(w, h, VK_FORMAT_R16G16B16A16_SFLOAT)
    static ImageDesc renderTarget(uint32_t width, uint32_t height, VkFormat format);
};

VkImageCreateInfo imageCreateInfo(const ImageDesc& desc);
// The view type of an image's default view: cube (array), 3D, 2D array or 2D.
VkImageViewType defaultViewType(const ImageDesc& desc);
VkImageAspectFlags aspectOf(VkFormat format);

using ImageView = ImageViewHandle;

class Image {
public:
    Image() = default;
    // Creates the image with its own (sub-allocated) memory and its default view.
    Image(Context& context, const ImageDesc& desc);
    // Creates the image bound to memory owned by someone else (who must outlive the image's use).
    Image(Context& context, const ImageDesc& desc, const ExternalMemory& memory);
    ~Image();
    Image(Image&& other) noexcept;
    Image& operator=(Image&& other) noexcept;
    Image(const Image&) = delete;
    Image& operator=(const Image&) = delete;

    VkImage handle() const { return mImage; }
    VkImageView view() const { return mView.get(); }
    const ImageDesc& desc() const { return mDesc; }
    VkImageAspectFlags aspect() const { return aspectOf(mDesc.format); }
    explicit operator bool() const { return mImage != VK_NULL_HANDLE; }
    // The device memory bound to the image (its allocation's size; 0 for external memory).
    VkDeviceSize memoryBytes() const { return mAllocation.size; }

    // Where the host writes mip `mip`, layer `layer` of a hostWritten image: its first texel in the
    // mapped memory and the bytes from one row to the next. Preconditions: desc().hostWritten; the
    // host writes only while the image is PREINITIALIZED, before Uploader::hostWritten moves it (host
    // access is defined in that layout, not in the one the shaders read).
    struct HostTexels {
        std::byte* data;
        VkDeviceSize rowPitch;
    };
    HostTexels hostTexels(uint32_t mip, uint32_t layer = 0) const;

    // A view of mips [baseMip, baseMip + mipCount) and layers [baseLayer, baseLayer + layerCount).
    ImageView createView(VkImageViewType type, uint32_t baseMip, uint32_t mipCount, uint32_t baseLayer,
                         uint32_t layerCount) const;
    // A view of each mip alone with all its layers — a 2D array for layered images (cubes too), else
    // 2D — as storage writes of one mip at a time need. Precondition: a 2D image (depth 1).
    std::vector<ImageView> createMipViews() const;

private:
    void create(Context& context, const ImageDesc& desc);
    void release();
    Context* mContext = nullptr;
    VkImage mImage = VK_NULL_HANDLE;
    Allocation mAllocation;  // empty for external memory
    ImageView mView;
    ImageDesc mDesc;
};

}  // namespace candela::vk
