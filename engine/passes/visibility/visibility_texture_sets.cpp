#include "passes/visibility/visibility_texture_sets.h"

#include <map>

namespace candela::passes {

TextureSets textureSetsOf(const gpu_scene::GpuScene& scene) {
    TextureSets out;
    using Slots = std::vector<std::pair<VkImageView, VkSampler>>;
    std::map<Slots, uint32_t> index;
    const auto materials = static_cast<uint32_t>(scene.scene().materials.size());
    for (uint32_t material = 0; material < materials; ++material) {
        Slots slots;
        for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot) {
            const gpu_scene::GpuScene::Binding b = scene.texture(material, slot);
            slots.emplace_back(b.view, b.sampler);
        }
        for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot) {
            const gpu_scene::GpuScene::Binding b = scene.layerTexture(material, slot);
            slots.emplace_back(b.view, b.sampler);
        }
        const auto [it, added] = index.try_emplace(std::move(slots), static_cast<uint32_t>(out.firstMaterial.size()));
        if (added) {
            const scene::Material& m = scene.scene().materials[material];
            uint32_t core = 0, layer = 0;
            for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot)
                if (m.texture(slot).present() || scene::kCoreTextureSlots[slot].normalMap) core |= 1u << slot;
            for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot)
                if (m.layerTexture(slot).present() || scene::kLayerTextureSlots[slot].normalMap) layer |= 1u << slot;
            out.firstMaterial.push_back(material);
            out.coreSlots.push_back(core);
            out.layerSlots.push_back(layer);
        }
        out.ofMaterial.push_back(it->second);
    }
    return out;
}

}  // namespace candela::passes
