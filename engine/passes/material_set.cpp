#include "passes/material_set.h"

#include "passes/forward_blocks.h"
#include "shared/scene_data.h"

namespace candela::passes {

VkDescriptorSet writeMaterialSet(vk::Context& context, vk::DescriptorAllocator& allocator, const vk::Program& program,
                                 const scene::GpuScene& scene, uint32_t material, VkBuffer layers) {
    vk::DescriptorWriter writer(program, 1);
    for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot) {
        const scene::GpuScene::Binding b = scene.texture(material, slot);
        writer.image(scene::kCoreTextureSlots[slot].sampler, b.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, b.sampler);
    }
    if (layers != VK_NULL_HANDLE) {
        writer.buffer(ForwardBlock<shading::MaterialLayerData>::name, layers);
        // The program may be specialized to the material's layers: only their textures are declared.
        for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot) {
            const char* name = scene::kLayerTextureSlots[slot].sampler;
            if (!program.declares(1, name)) continue;
            const scene::GpuScene::Binding b = scene.layerTexture(material, slot);
            writer.image(name, b.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, b.sampler);
        }
    }
    return writer.commit(context, allocator);
}

}  // namespace candela::passes
