#include "passes/drawing/draw_list.h"

#include "geometry/mesh_lod.h"
#include "scene/frustum.h"

#include <algorithm>
#include <cstdio>
#include <tuple>

namespace candela::passes {

namespace {

// The level of detail `draw` is drawn at from `view` on a target `height` pixels tall: the coarsest
// of its chain whose error covers at most `maxPixels` (its full detail without a chain).
scene::LodLevel levelOf(const scene::Scene& scene, const scene::Draw& draw, const scene::ViewSetup& view, uint32_t height,
                        float maxPixels) {
    if (draw.lod < 0 || !(maxPixels > 0.0f)) return {draw.firstIndex, draw.indexCount, 0.0f};
    float scale = geometry::maxScale(draw.world);
    if (draw.instanceCount > 0) {
        float instanceScale = 0.0f;
        for (uint32_t i = 0; i < draw.instanceCount; ++i)
            instanceScale = std::max(instanceScale, geometry::maxScale(scene.instances[draw.firstInstance + i]));
        scale *= instanceScale;
    }
    const scene::LodChain& chain = scene.lodChains[size_t(draw.lod)];
    return chain.levels[geometry::selectLod(chain, scale, geometry::pixelsPerUnit(view, height, draw.bounds), maxPixels)];
}

bool sortedBackToFront(DrawRange range) { return range == DrawRange::Transmissive || range == DrawRange::Blended; }

std::string formatPixels(float pixels) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(pixels));
    return text;
}

}  // namespace

DrawRange rangeOf(const MaterialKey& key, bool transmission) {
    if (key.transmissive && transmission) return DrawRange::Transmissive;
    if (key.blend) return DrawRange::Blended;
    if (key.topology != scene::Topology::Triangles) return DrawRange::PointsAndLines;
    return key.alphaMask ? DrawRange::Masked : DrawRange::Opaque;
}

const char* drawRangeName(DrawRange range) {
    switch (range) {
    case DrawRange::Opaque: return "opaque";
    case DrawRange::Masked: return "masked";
    case DrawRange::PointsAndLines: return "points and lines";
    case DrawRange::Transmissive: return "transmissive";
    case DrawRange::Blended: return "blended";
    }
    return "?";
}

MaterialKey materialKeyOf(const scene::Material& m) {
    const bool layered = !m.unlit && m.layers() != 0;
    return {.unlit = m.unlit,
            .normalMap = !m.unlit && m.normal.present(),
            .alphaMask = m.alphaMode == scene::AlphaMode::Mask,
            .blend = m.alphaMode == scene::AlphaMode::Blend,
            .layers = layered ? m.layers() : 0,
            .transmissive = layered && (m.layers() & scene::kLayerTransmission) != 0};
}

MaterialKey materialKeyOf(const scene::Material& material, const scene::Draw& draw) {
    MaterialKey key = materialKeyOf(material);
    key.topology = draw.topology;
    // Unlit, drawn by the program of the material's layers still: its material set has their layout.
    if (draw.unshaded) {
        key.unlit = true;
        key.normalMap = false;
        key.transmissive = false;
    }
    return key;
}

MaterialKeys MaterialKeys::of(const scene::Scene& scene) {
    MaterialKeys out;
    const auto indexOf = [&](const MaterialKey& key) {
        const auto index = uint32_t(std::find(out.keys.begin(), out.keys.end(), key) - out.keys.begin());
        if (index == out.keys.size()) out.keys.push_back(key);
        return index;
    };
    out.ofMaterial.reserve(scene.materials.size());
    for (const scene::Material& m : scene.materials) out.ofMaterial.push_back(indexOf(materialKeyOf(m)));
    const auto addShaped = [&](uint32_t material, const scene::Draw& draw) {
        out.ofShapedMaterial.try_emplace({material, draw.topology, draw.unshaded},
                                         indexOf(materialKeyOf(scene.materials[material], draw)));
    };
    for (const scene::Draw& draw : scene.draws)
        if (draw.topology != scene::Topology::Triangles) addShaped(draw.material, draw);
    for (const scene::DrawVariants& variants : scene.drawVariants)
        if (const scene::Draw& draw = scene.draws[variants.draw]; draw.topology != scene::Topology::Triangles) {
            addShaped(variants.defaultMaterial, draw);
            for (const auto& [variant, material] : variants.materials) addShaped(material, draw);
        }
    return out;
}

uint32_t MaterialKeys::keyOf(uint32_t material, const scene::Draw& draw) const {
    if (draw.topology == scene::Topology::Triangles) return ofMaterial[material];
    return ofShapedMaterial.at({material, draw.topology, draw.unshaded});
}

std::span<const DrawListItem> DrawList::range(DrawRange r) const { return ranges(r, r); }

std::span<const DrawListItem> DrawList::ranges(DrawRange first, DrawRange last) const {
    const uint32_t begin = rangeStart[size_t(first)], end = rangeStart[size_t(last) + 1];
    return std::span<const DrawListItem>(items).subspan(begin, end - begin);
}

std::vector<DrawListItem> DrawList::backToFront(DrawRange a, DrawRange b) const {
    const std::span<const DrawListItem> first = range(a), second = range(b);
    std::vector<DrawListItem> out(first.size() + second.size());
    std::merge(first.begin(), first.end(), second.begin(), second.end(), out.begin(),
               [](const DrawListItem& x, const DrawListItem& y) { return x.depth > y.depth; });
    return out;
}

DrawList buildDrawList(const DrawListInputs& in) {
    DrawList list;
    const scene::Frustum frustum(in.view.viewProjection);
    uint32_t drawData = 0;  // the draw buffer holds one entry per draw, one per instance for instanced ones
    for (uint32_t i = 0; i < in.draws.size(); drawData += std::max(in.draws[i].instanceCount, 1u), ++i) {
        const scene::Draw& draw = in.draws[i];
        if (draw.hidden) {
            ++list.hiddenDraws;
            continue;
        }
        ++list.draws;
        list.instances += draw.instanceCount;
        const uint32_t instances = std::max(draw.instanceCount, 1u);
        DrawStats& stats = list.stats;
        ++stats.sceneDraws;
        const bool triangles = draw.topology == scene::Topology::Triangles;
        if (triangles) stats.sceneTriangles += uint64_t(draw.indexCount / 3) * instances;
        if (in.selection.frustumCulling && !frustum.intersects(draw.bounds)) {
            ++stats.culledDraws;
            continue;
        }
        const scene::LodLevel level = levelOf(in.scene, draw, in.view, in.targetHeight, in.selection.lodErrorPixels);
        stats.coarserDraws += level.firstIndex != draw.firstIndex;
        ++stats.submittedDraws;
        if (triangles) stats.submittedTriangles += uint64_t(level.indexCount / 3) * instances;
        else (draw.topology == scene::Topology::Lines ? stats.submittedLines : stats.submittedPoints) +=
            uint64_t(level.indexCount / scene::indicesPerPrimitive(draw.topology)) * instances;
        const uint32_t key = in.keys.keyOf(draw.material, draw);
        const glm::vec3 centre = 0.5f * (draw.bounds.min + draw.bounds.max);
        list.items.push_back({.draw = i,
                              .material = draw.material,
                              .key = key,
                              .firstIndex = level.firstIndex,
                              .indexCount = level.indexCount,
                              .drawData = drawData,
                              .instances = instances,
                              .depth = glm::length(centre - in.view.eye),
                              .flipWinding = draw.flipWinding,
                              .doubleSided = in.scene.materials[draw.material].doubleSided,
                              .range = rangeOf(in.keys.keys[key], in.transmission)});
    }
    // The sort key: the range first; then material key and material (grouping pipelines and
    // material sets), or distance back to front. Stable: equal keys keep the scene's order.
    std::stable_sort(list.items.begin(), list.items.end(), [](const DrawListItem& a, const DrawListItem& b) {
        if (a.range != b.range) return a.range < b.range;
        if (sortedBackToFront(a.range)) return a.depth > b.depth;
        return std::tie(a.key, a.material) < std::tie(b.key, b.material);
    });
    uint32_t item = 0;
    for (size_t r = 0; r < kDrawRangeCount; ++r) {
        list.rangeStart[r] = item;
        while (item < list.items.size() && size_t(list.items[item].range) == r) ++item;
    }
    list.rangeStart[kDrawRangeCount] = item;
    return list;
}

std::string describeSelection(const DrawList& list, const options::DrawSelection& selection) {
    const DrawStats& s = list.stats;
    return "draws: " + std::to_string(s.submittedDraws) + " of " + std::to_string(s.sceneDraws) + " submitted (" +
           std::to_string(s.culledDraws) + " outside the view frustum" + (selection.frustumCulling ? "" : ", culling off") +
           "), " + std::to_string(s.submittedTriangles) + " of " + std::to_string(s.sceneTriangles) + " triangles" +
           (s.submittedLines ? ", " + std::to_string(s.submittedLines) + " lines" : std::string()) +
           (s.submittedPoints ? ", " + std::to_string(s.submittedPoints) + " points" : std::string()) + "; " +
           std::to_string(s.coarserDraws) + " draws at a coarser level of detail (" +
           (selection.lodErrorPixels > 0.0f ? "error ≤ " + formatPixels(selection.lodErrorPixels) + " px"
                                            : std::string("levels of detail off")) +
           ")";
}

}  // namespace candela::passes
