#include "vk/image.h"

#include "core/errors.h"
#include "vk/check.h"
#include "vk/context.h"

#include <string>
#include <utility>

namespace candela::vk {
namespace {
// Usages that allow an image view; transfer-only images get no default view.
constexpr VkImageUsageFlags kViewUsages = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                          VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                          VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT;
}  // namespace

ImageDesc ImageDesc::renderTarget(uint32_t width, uint32_t height, VkFormat format) {
    const bool depth = aspectOf(format) & VK_IMAGE_ASPECT_DEPTH_BIT;
    return {.width = width,
            .height = height,
            .format = format,
            .usage = static_cast<VkImageUsageFlags>(
                (depth ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) |
                VK_IMAGE_USAGE_SAMPLED_BIT)};
}

VkImageAspectFlags aspectOf(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D16_UNORM:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_X8_D24_UNORM_PACK32: return VK_IMAGE_ASPECT_DEPTH_BIT;
        case VK_FORMAT_D16_UNORM_S8_UINT:
        case VK_FORMAT_D24_UNORM_S8_UINT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT: return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
        case VK_FORMAT_S8_UINT: return VK_IMAGE_ASPECT_STENCIL_BIT;
        default: return VK_IMAGE_ASPECT_COLOR_BIT;
    }
}

VkImageViewType defaultViewType(const ImageDesc& desc) {
    if (desc.cube) return desc.arrayLayers > 6 ? VK_IMAGE_VIEW_TYPE_CUBE_ARRAY : VK_IMAGE_VIEW_TYPE_CUBE;
    if (desc.depth > 1) return VK_IMAGE_VIEW_TYPE_3D;
    return desc.arrayLayers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
}

VkImageCreateInfo imageCreateInfo(const ImageDesc& desc) {
    return {.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
            .flags = desc.cube ? VkImageCreateFlags(VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT) : 0u,
            .imageType = desc.depth > 1 ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D,
            .format = desc.format,
            .extent = {desc.width, desc.height, desc.depth},
            .mipLevels = desc.mipLevels,
            .arrayLayers = desc.arrayLayers,
            .samples = static_cast<VkSampleCountFlagBits>(desc.samples),
            .tiling = desc.hostWritten ? VK_IMAGE_TILING_LINEAR : VK_IMAGE_TILING_OPTIMAL,
            .usage = desc.usage,
            .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
            .initialLayout = desc.hostWritten ? VK_IMAGE_LAYOUT_PREINITIALIZED : VK_IMAGE_LAYOUT_UNDEFINED};
}

void Image::create(Context& context, const ImageDesc& desc) {
    mContext = &context;
    mDesc = desc;
    const VkImageCreateInfo info = imageCreateInfo(desc);
    VK_CHECK(vkCreateImage(context.device(), &info, nullptr, &mImage));
    context.countCreated();
    context.setName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(mImage), desc.name);
}

Image::Image(Context& context, const ImageDesc& desc) {
    create(context, desc);
    try {
        VkMemoryRequirements requirements;
        vkGetImageMemoryRequirements(context.device(), mImage, &requirements);
        try {
            mAllocation = desc.hostWritten ? context.allocator().allocate(requirements, MemoryUsage::Stream, ResourceTiling::Linear)
                                           : context.allocator().allocate(requirements, desc.memory, ResourceTiling::Optimal);
        } catch (const OutOfDeviceMemory& e) {
            throw OutOfDeviceMemory("cannot allocate " + formatBytes(requirements.size) + " for image '" +
                                    (desc.name ? desc.name : "unnamed") + "': " + e.what());
        }
        VK_CHECK(vkBindImageMemory(context.device(), mImage, mAllocation.memory, mAllocation.offset));
        if (desc.usage & kViewUsages) mView = createView(defaultViewType(desc), 0, desc.mipLevels, 0, desc.arrayLayers);
    } catch (...) {
        release();
        throw;
    }
}

Image::Image(Context& context, const ImageDesc& desc, const ExternalMemory& memory) {
    create(context, desc);
    try {
        VkMemoryRequirements requirements;
        vkGetImageMemoryRequirements(context.device(), mImage, &requirements);
        checkFits(requirements, memory, desc.name);
        VK_CHECK(vkBindImageMemory(context.device(), mImage, memory.memory, memory.offset));
        if (desc.usage & kViewUsages) mView = createView(defaultViewType(desc), 0, desc.mipLevels, 0, desc.arrayLayers);
    } catch (...) {
        release();
        throw;
    }
}

Image::HostTexels Image::hostTexels(uint32_t mip, uint32_t layer) const {
    if (!mDesc.hostWritten || !mAllocation.mapped || mip >= mDesc.mipLevels || layer >= mDesc.arrayLayers)
        throw InternalError(std::string("Image::hostTexels: image '") + (mDesc.name ? mDesc.name : "unnamed") +
                            "' is not host-written, or has no such mip or layer");
    const VkImageSubresource subresource{aspect(), mip, layer};
    VkSubresourceLayout layout;
    vkGetImageSubresourceLayout(mContext->device(), mImage, &subresource, &layout);
    return {mAllocation.mapped + layout.offset, layout.rowPitch};
}

Image::~Image() { release(); }

Image::Image(Image&& other) noexcept
    : mContext(std::exchange(other.mContext, nullptr)),
      mImage(std::exchange(other.mImage, VK_NULL_HANDLE)),
      mAllocation(std::exchange(other.mAllocation, {})),
      mView(std::move(other.mView)),
      mDesc(other.mDesc) {}

Image& Image::operator=(Image&& other) noexcept {
    if (this != &other) {
        release();
        mContext = std::exchange(other.mContext, nullptr);
        mImage = std::exchange(other.mImage, VK_NULL_HANDLE);
        mAllocation = std::exchange(other.mAllocation, {});
        mView = std::move(other.mView);
        mDesc = other.mDesc;
    }
    return *this;
}

std::vector<ImageView> Image::createMipViews() const {
    const bool layered = mDesc.arrayLayers > 1 || mDesc.cube;
    std::vector<ImageView> views;
    for (uint32_t mip = 0; mip < mDesc.mipLevels; ++mip)
        views.push_back(createView(layered ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D, mip, 1, 0, mDesc.arrayLayers));
    return views;
}

ImageView Image::createView(VkImageViewType type, uint32_t baseMip, uint32_t mipCount, uint32_t baseLayer,
                            uint32_t layerCount) const {
    const VkImageViewCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                     .image = mImage,
                                     .viewType = type,
                                     .format = mDesc.format,
                                     .subresourceRange = {aspect(), baseMip, mipCount, baseLayer, layerCount}};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(mContext->device(), &info, nullptr, &view));
    return ImageView(*mContext, view);
}

void Image::release() {
    mView = ImageView();  // the view is deferred before the image it belongs to
    if (!mImage) return;
    Context* context = mContext;
    context->defer([context, image = mImage, allocation = mAllocation] {
        vkDestroyImage(context->device(), image, nullptr);
        context->allocator().free(allocation);
        context->countDestroyed();
    });
    mImage = VK_NULL_HANDLE;
    mAllocation = {};
}

}  // namespace candela::vk
