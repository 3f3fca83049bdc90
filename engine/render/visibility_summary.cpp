#include "render/visibility_summary.h"

namespace candela {

std::string explainVisibility(const VisibilitySummary& s) {
    std::string line = "shading path: visibility — " + std::to_string(s.draws) + " opaque and masked draws into a " +
                       std::to_string(s.width) + "×" + std::to_string(s.height) +
                       (s.samples > 1 ? " " + std::to_string(s.samples) + "-sample" : std::string()) +
                       " visibility image, classified in " + std::to_string(s.tiles) + " tiles of " +
                       std::to_string(s.tileWidth) + "×" + std::to_string(s.tileHeight) +
                       "; one compute dispatch per shading list (variant × texture set):";
    for (const VisibilitySummary::List& list : s.lists)
        line += " " + list.variant + "/textures" + std::to_string(list.textureSet) + " ×" + std::to_string(list.draws);
    if (s.samples > 1)
        line += "; then, on triangle edges, each further distinct triangle of a pixel's samples (the resolve in the shading)";
    return line;
}

}  // namespace candela
