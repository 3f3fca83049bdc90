#include "passes/drawing/shading_summary.h"

namespace candela::passes {

ShadingSummary summarizeShading(const DrawList& list, const MaterialKeys& keys, const scene::Scene& scene,
                                uint32_t lightCount, const FrameVariant& frame, bool posed) {
    ShadingSummary out{.draws = list.draws,
                       .instances = list.instances,
                       .posed = posed,
                       .hiddenDraws = list.hiddenDraws,
                       .lights = lightCount > 0,
                       .lodDecision = scene.report.geometry.lodDecision};
    // Draws per material key, then per variant name (keys of one frame may share a variant).
    std::vector<uint32_t> perKey(keys.keys.size(), 0);
    for (const DrawListItem& item : list.items) ++perKey[item.key];
    for (uint32_t key = 0; key < perKey.size(); ++key)
        if (perKey[key]) out.variants[shadingVariant(keys.keys[key], frame).name()] += perKey[key];
    // Unlit variants also draw points and lines without normals (Draw::unshaded).
    for (const MaterialKey& key : keys.keys) out.unlit = out.unlit || key.unlit;
    for (uint32_t material = 0; material < scene.materials.size(); ++material) {
        const scene::Material& m = scene.materials[material];
        out.normalMaps = out.normalMaps || m.normal.present();
        if (const uint32_t layers = keys[material].layers) out.layered.push_back({m.name, layers});
    }
    return out;
}

std::vector<std::string> explainShading(const ShadingSummary& summary, const DrawList& list,
                                        const options::DrawSelection& selection) {
    std::vector<std::string> out;
    std::string used = "forward: " + std::to_string(summary.draws) + " draws" +
                       (summary.instances ? " (" + std::to_string(summary.instances) + " instances in instanced draws)"
                                          : std::string()) +
                       "; variants:";
    for (const auto& [name, count] : summary.variants) used += " " + name + " ×" + std::to_string(count);
    out.push_back(used);
    out.push_back(describeSelection(list, selection));
    if (!summary.lodDecision.empty()) out.push_back(summary.lodDecision);
    if (summary.posed)
        out.push_back("animated: draw matrices of this frame's pose, written by the CPU into a per-frame buffer" +
                      (summary.hiddenDraws
                           ? " (" + std::to_string(summary.hiddenDraws) + " draws hidden or scaled to nothing, not drawn)"
                           : std::string()));
    else if (summary.hiddenDraws)
        out.push_back("left out: " + std::to_string(summary.hiddenDraws) + " draws of hidden nodes (KHR_node_visibility)");
    if (!summary.lights) out.emplace_back("left out: light loop (no punctual lights)");
    if (!summary.normalMaps) out.emplace_back("left out: normal mapping / TBN work (no material has a normal texture)");
    if (!summary.unlit) out.emplace_back("left out: unlit variant (no KHR_materials_unlit material, no unshaded point or line)");
    for (const ShadingSummary::LayeredMaterial& material : summary.layered)
        out.push_back("material '" + material.name + "' pays for layers: " + plusLayerNames(material.layers).substr(1) +
                      " (the layered forward program)");
    if (summary.layered.empty())
        out.emplace_back("left out: material layers (no material uses a KHR_materials_* layer; core forward program only)");
    return out;
}

}  // namespace candela::passes
