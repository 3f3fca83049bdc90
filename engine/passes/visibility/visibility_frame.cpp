#include "passes/visibility/visibility_frame.h"

#include <algorithm>
#include <map>

namespace candela::passes {

ShadingVariant computeShadingVariant(const ShadingVariant& drawn) {
    ShadingVariant v = drawn;
    v.alphaMask = false;
    v.blend = false;
    v.alphaToCoverage = false;
    return v;
}

std::optional<VisibilityFrameTables> visibilityFrameTables(std::span<const DrawListItem> items, const MaterialKeys& keys,
                                                           std::span<const uint32_t> textureSetOf, const FrameVariant& frame,
                                                           std::span<const int32_t> vertexOffset) {
    VisibilityFrameTables out;
    uint32_t entries = 0;
    for (const DrawListItem& item : items) entries = std::max(entries, item.drawData + item.instances);
    out.draws.resize(entries);
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> listOf;  // (key, texture set) → list
    for (const DrawListItem& item : items) {
        const uint32_t textureSet = textureSetOf[item.material];
        auto [found, added] = listOf.try_emplace({item.key, textureSet}, 0);
        if (added) {
            const ShadingVariant v = computeShadingVariant(shadingVariant(keys.keys[item.key], frame));
            const auto same = std::find_if(out.lists.begin(), out.lists.end(),
                                           [&](const ShadingList& l) { return l.variant == v && l.textureSet == textureSet; });
            found->second = static_cast<uint32_t>(same - out.lists.begin());
            if (same == out.lists.end()) {
                // With MSAA each list has a tile list per distinct triangle a pixel's samples show.
                const size_t limit = CANDELA_VISIBILITY_MAX_LISTS / std::max(frame.samples, 1u);
                if (out.lists.size() == limit) return std::nullopt;
                out.lists.push_back({.variant = v, .textureSet = textureSet});
            }
        }
        const uint32_t list = found->second;
        ++out.lists[list].items;
        const int32_t offset = vertexOffset.empty() ? CANDELA_REST_VERTICES : vertexOffset[item.draw];
        for (uint32_t instance = 0; instance < item.instances; ++instance)
            out.draws[item.drawData + instance] = {.firstIndex = item.firstIndex,
                                                   .vertexOffset = offset,
                                                   .list = list,
                                                   .flipWinding = item.flipWinding ? 1u : 0u};
    }
    return out;
}

glm::uvec2 visibilityTileSize(VkPhysicalDeviceType deviceType) {
    return deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? glm::uvec2(8, 1) : glm::uvec2(8, 8);
}

shading::VisibilityFrame visibilityExtent(uint32_t width, uint32_t height, glm::uvec2 tile, uint32_t lists, uint32_t samples) {
    const uint32_t tilesX = (width + tile.x - 1) / tile.x;
    const uint32_t tilesY = (height + tile.y - 1) / tile.y;
    const uint32_t tileLists = samples * lists;  // with MSAA a pixel's k-th distinct triangle: list k · lists + l
    return {.extent = glm::uvec4(width, height, tilesX, tilesX * tilesY),
            .lists = glm::uvec4(tileLists, std::max(1u, (tileLists + 31) / 32), tile),
            .samples = glm::uvec4(samples, lists, 0, 0)};
}

}  // namespace candela::passes
