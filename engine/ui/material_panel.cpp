// The material inspector: the scene's materials (pick one from the list, or left-click a mesh),
// what the selected one uses, and its factors — the reflected members of the forward shaders'
// MaterialData and, for a material with layers, of the layered program's MaterialLayerData, edited
// live through the parameter registry ("forward", "Materials[i]" and "MaterialLayers[i]").

#include "ui/panels.h"
#include "ui/parameter_widgets.h"
#include "ui/viewer.h"

#include <imgui.h>

#include <span>
#include <string>

namespace candela::ui {

namespace {

std::string materialLabel(const scene::Scene& scene, uint32_t i) {
    const std::string& name = scene.materials[i].name;
    return std::to_string(i) + ": " + (name.empty() ? std::string("(unnamed)") : name);
}

const char* alphaModeName(scene::AlphaMode mode) {
    switch (mode) {
        case scene::AlphaMode::Mask: return "mask";
        case scene::AlphaMode::Blend: return "blend";
        default: return "opaque";
    }
}

}  // namespace

void drawMaterialPanel(Viewer& viewer) {
    const scene::Scene& scene = viewer.scene();
    if (scene.materials.empty()) {
        ImGui::TextDisabled("the scene has no materials");
        return;
    }
    uint32_t selected = std::min<uint32_t>(viewer.selectedMaterial(), uint32_t(scene.materials.size() - 1));
    if (!scene.variants.empty()) {
        // KHR_materials_variants: the file's variants, and its default materials.
        const std::optional<uint32_t> current = viewer.variant();
        if (ImGui::BeginCombo("variant", current ? scene.variants[*current].c_str() : "(default materials)")) {
            if (ImGui::Selectable("(default materials)", !current)) viewer.selectVariant(std::nullopt);
            for (uint32_t v = 0; v < scene.variants.size(); ++v)
                if (ImGui::Selectable((scene.variants[v] + "##variant" + std::to_string(v)).c_str(), current == v))
                    viewer.selectVariant(v);
            ImGui::EndCombo();
        }
    }
    if (ImGui::BeginCombo("material", materialLabel(scene, selected).c_str())) {
        for (uint32_t i = 0; i < scene.materials.size(); ++i)
            if (ImGui::Selectable(materialLabel(scene, i).c_str(), i == selected)) viewer.selectMaterial(i);
        ImGui::EndCombo();
    }
    ImGui::TextDisabled("or left-click a mesh");
    const scene::Material& m = scene.materials[selected];
    std::string textures;
    // Named as glTF names them (the forward programs' samplers: "baseColorTexture", …).
    for (const auto& table : {std::span<const scene::TextureSlot>(scene::kCoreTextureSlots),
                              std::span<const scene::TextureSlot>(scene::kLayerTextureSlots)})
        for (const scene::TextureSlot& slot : table)
            if ((m.*slot.field).present()) textures += (textures.empty() ? "" : ", ") + std::string(slot.sampler);
    ImGui::TextWrapped("textures: %s", textures.empty() ? "none" : textures.c_str());
    ImGui::Text("alpha: %s%s%s", alphaModeName(m.alphaMode), m.doubleSided ? ", double-sided" : "", m.unlit ? ", unlit" : "");
    shader::ParameterRegistry& registry = viewer.renderer().parameters();
    if (const auto* block = registry.find("forward", "Materials[" + std::to_string(selected) + "]"))
        drawParameterBlock(registry, *block);
    if (m.layers() != 0) {
        std::string layers;
        for (std::string_view name : scene::layerNames(m.layers())) (layers += layers.empty() ? "" : ", ") += name;
        textDisabledWrapped("layers: " + layers);
    }
    if (const auto* block = registry.find("forward", "MaterialLayers[" + std::to_string(selected) + "]"))
        drawParameterBlock(registry, *block);
}

}  // namespace candela::ui
