#include "render/posed_summary.h"

#include <vector>

namespace candela {

std::string explainPosed(const PosedSummary& summary) {
    const auto count = [](uint32_t n, const char* one) { return std::to_string(n) + " " + one + (n == 1 ? "" : "s"); };
    std::vector<std::string> parts;
    if (summary.materials)
        parts.push_back(count(summary.materials, "material") +
                        (summary.materialLayers ? " (posed_materials, posed_material_layers)" : " (posed_materials)"));
    if (summary.lights)
        parts.push_back(count(summary.lights, "light") +
                        (summary.lightsWritten ? " (posed_lights)" : " (not drawn: --scene-lights off)"));
    if (summary.cameras) parts.push_back(count(summary.cameras, "camera") + " (the view of a glTF camera follows)");
    if (parts.empty()) return "";
    std::string line = "animated properties (KHR_animation_pointer), written by the CPU per frame:";
    for (size_t i = 0; i < parts.size(); ++i) line += (i ? ", " : " ") + parts[i];
    return line;
}

}  // namespace candela
