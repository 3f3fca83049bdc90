#include "passes/drawing/scene_bindings.h"

#include "passes/drawing/scene_blocks.h"
#include "shared/scene_data.h"

namespace candela::passes {

SceneBuffers sceneBuffersOf(const gpu_scene::GpuScene& scene) {
    return {.lights = scene.lightBuffer(), .draws = scene.drawBuffer(), .materials = scene.materialBuffer()};
}

VkDescriptorSet writeSceneSet(vk::Context& context, vk::DescriptorAllocator& allocator, const vk::Program& program,
                              const SceneBuffers& buffers) {
    vk::DescriptorWriter writer(program, 0);
    const std::pair<std::string_view, VkBuffer> blocks[] = {{SceneBlock<shading::LightData>::name, buffers.lights},
                                                            {SceneBlock<shading::DrawData>::name, buffers.draws},
                                                            {SceneBlock<shading::MaterialData>::name, buffers.materials}};
    for (const auto& [name, buffer] : blocks)
        if (program.declares(0, name)) writer.buffer(name, buffer);
    return writer.commit(context, allocator);
}

VkDescriptorSet frameSceneSet(const graph::PassContext& ctx, const vk::Program& program, const gpu_scene::GpuScene& scene,
                              const PosedBuffers& declared, VkDescriptorSet sceneSet) {
    const auto posed = [&](graph::BufferId buffer, std::string_view block) { return buffer.valid() && program.declares(0, block); };
    if (!posed(declared.lights, SceneBlock<shading::LightData>::name) && !posed(declared.draws, SceneBlock<shading::DrawData>::name) &&
        !posed(declared.materials, SceneBlock<shading::MaterialData>::name))
        return sceneSet;
    SceneBuffers buffers = sceneBuffersOf(scene);
    if (declared.lights.valid()) buffers.lights = ctx.buffer(declared.lights);
    if (declared.draws.valid()) buffers.draws = ctx.buffer(declared.draws);
    if (declared.materials.valid()) buffers.materials = ctx.buffer(declared.materials);
    return writeSceneSet(ctx.context(), ctx.descriptors(), program, buffers);
}

VkDescriptorSet writeMaterialSet(vk::Context& context, vk::DescriptorAllocator& allocator, const vk::Program& program,
                                 const gpu_scene::GpuScene& scene, uint32_t material, VkBuffer layers) {
    vk::DescriptorWriter writer(program, 1);
    for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot) {
        const gpu_scene::GpuScene::Binding b = scene.texture(material, slot);
        writer.image(scene::kCoreTextureSlots[slot].sampler, b.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, b.sampler);
    }
    if (layers != VK_NULL_HANDLE) {
        writer.buffer(SceneBlock<shading::MaterialLayerData>::name, layers);
        // The program may be specialized to the material's layers: only their textures are declared.
        for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot) {
            const char* name = scene::kLayerTextureSlots[slot].sampler;
            if (!program.declares(1, name)) continue;
            const gpu_scene::GpuScene::Binding b = scene.layerTexture(material, slot);
            writer.image(name, b.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, b.sampler);
        }
    }
    return writer.commit(context, allocator);
}

PosedMaterialSets::PosedMaterialSets(const graph::PassContext& ctx, const gpu_scene::GpuScene& scene, graph::BufferId declaredLayers,
                                     size_t slots)
    : mCtx(ctx), mScene(scene), mLayers(declaredLayers), mSets(declaredLayers.valid() ? slots : 0, VK_NULL_HANDLE) {}

VkDescriptorSet PosedMaterialSets::get(size_t slot, bool layered, const vk::Program& program, uint32_t material,
                                       VkDescriptorSet sceneSet) {
    if (!layered || mSets.empty()) return sceneSet;
    VkDescriptorSet& set = mSets[slot];
    if (set == VK_NULL_HANDLE)
        set = writeMaterialSet(mCtx.context(), mCtx.descriptors(), program, mScene, material, mCtx.buffer(mLayers));
    return set;
}

}  // namespace candela::passes
