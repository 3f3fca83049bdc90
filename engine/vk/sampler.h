#pragma once
// Sampler creation from a small description.

#include "vk/handle.h"

namespace candela::vk {

struct SamplerDesc {
    VkFilter filter = VK_FILTER_LINEAR;     // magnification
    VkFilter minFilter = VK_FILTER_LINEAR;  // minification
    VkSamplerMipmapMode mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    VkSamplerAddressMode addressU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    VkSamplerAddressMode addressV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    VkSamplerAddressMode addressW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    float maxAnisotropy = 1.0f;  // > 1 only takes effect when samplerAnisotropy is enabled
    float maxLod = VK_LOD_CLAMP_NONE;
};

// Point sampling: nearest texel, nearest mip (exact texel reads, data shown as it is).
inline constexpr SamplerDesc kNearestSampler{.filter = VK_FILTER_NEAREST,
                                             .minFilter = VK_FILTER_NEAREST,
                                             .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST};

Sampler createSampler(Context& context, const SamplerDesc& desc);

}  // namespace candela::vk
