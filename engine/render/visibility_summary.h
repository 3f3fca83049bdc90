#pragma once
// VisibilitySummary: what a visibility-path frame did, as data — the draws rasterized into the
// visibility image, its size and samples, the classification tiles and one compute dispatch per
// shading list. Made by VisibilityPath::add, kept with the frame (Renderer::lastVisibility); tests
// assert its fields and explainVisibility puts it into the --explain line. Pure: no Vulkan.

#include <cstdint>
#include <string>
#include <vector>

namespace candela {

struct VisibilitySummary {
    uint32_t draws = 0;                        // opaque and masked draws rasterized
    uint32_t width = 0, height = 0;            // the visibility image
    uint32_t samples = 1;                      // its samples (more than 1: the resolve is in the shading)
    uint32_t tiles = 0;                        // classification tiles
    uint32_t tileWidth = 0, tileHeight = 0;    // a tile's pixels
    struct List {                              // a shading list: one compute dispatch
        std::string variant;                   // the shading variant's name (ShadingVariant::name)
        uint32_t textureSet = 0;
        uint32_t draws = 0;
        bool operator==(const List&) const = default;
    };
    std::vector<List> lists;
    bool operator==(const VisibilitySummary&) const = default;
};

// "shading path: visibility — N opaque and masked draws into a W×H[ S-sample] visibility image,
// classified in T tiles of X×Y; one compute dispatch per shading list (variant × texture set):
// VARIANT/texturesK ×N …[; then, on triangle edges, …]".
std::string explainVisibility(const VisibilitySummary& summary);

}  // namespace candela
