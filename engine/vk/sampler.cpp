#include "vk/sampler.h"

#include "vk/check.h"

#include <algorithm>

namespace candela::vk {

Sampler createSampler(Context& context, const SamplerDesc& desc) {
    const bool anisotropy = desc.maxAnisotropy > 1.0f && context.caps().features.samplerAnisotropy;
    const VkSamplerCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
        .magFilter = desc.filter,
        .minFilter = desc.minFilter,
        .mipmapMode = desc.mipmapMode,
        .addressModeU = desc.addressU,
        .addressModeV = desc.addressV,
        .addressModeW = desc.addressW,
        .anisotropyEnable = anisotropy ? VK_TRUE : VK_FALSE,
        .maxAnisotropy = anisotropy ? std::min(desc.maxAnisotropy, context.caps().limits.maxSamplerAnisotropy) : 1.0f,
        .minLod = 0.0f,
        .maxLod = desc.maxLod};
    VkSampler sampler = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSampler(context.device(), &info, nullptr, &sampler));
    return Sampler(context, sampler);
}

}  // namespace candela::vk
