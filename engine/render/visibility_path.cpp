#include "render/visibility_path.h"

#include "core/errors.h"
#include "vk/context.h"

#include <map>

namespace candela {

VisibilityPath::VisibilityPath(vk::Context& context) : mContext(context), mRaster(context), mClassify(context), mShade(context) {}

void VisibilityPath::setScene(const gpu_scene::GpuScene& scene, const passes::MaterialKeys& keys) {
    mScene = nullptr, mKeys = nullptr, mBound = false;
    mUnsupported = mContext.choices().visibilityUnsupported;
    if (!mUnsupported.empty()) return;
    const uint64_t range = mContext.caps().limits.maxStorageBufferRange;
    for (const auto& [what, bytes] : {std::pair("vertices", scene.vertexBytes()), std::pair("indices", scene.indexBytes())})
        if (bytes > range) {
            mUnsupported = std::string("the scene's ") + what + " (" + formatBytes(bytes) +
                           ") pass the device's maxStorageBufferRange (" + formatBytes(range) + ")";
            return;
        }
    mTextureSets = passes::textureSetsOf(scene);
    mScene = &scene;
    mKeys = &keys;
}

std::pair<options::ShadingPath, std::string> defaultShadingPath(const vk::Context& context) {
    if (!context.choices().visibilityUnsupported.empty())
        return {options::ShadingPath::Forward, "the device's default: the visibility path needs " + context.choices().visibilityUnsupported};
    if (context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU)
        return {options::ShadingPath::Forward,
                "the device's default: on lavapipe the visibility path measured faster on the sphere grids, slower on "
                "DamagedHelmet and at 4 samples (docs/shading-paths.md)"};
    return {options::ShadingPath::Forward,
            "the device's default: on the one GPU measured, an NVIDIA H200 (a compute GPU), the visibility path was "
            "faster on the sphere grids, slower on DamagedHelmet (docs/shading-paths.md)"};
}

bool VisibilityPath::samplesIntegerImages(uint32_t samples) const {
    return samples == 1 || (mContext.caps().limits.sampledImageIntegerSampleCounts & samples) != 0;
}

std::optional<passes::VisibilityFrameTables> VisibilityPath::tables(const FrameDesc& desc) const {
    const std::span<const passes::DrawListItem> items = desc.list.ranges(passes::DrawRange::Opaque, passes::DrawRange::Masked);
    return passes::visibilityFrameTables(items, desc.keys, mTextureSets.ofMaterial, desc.inputs.variant, desc.inputs.vertexOffset);
}

passes::DrawTarget VisibilityPath::add(Frame& frame, const FrameDesc& desc, const passes::VisibilityFrameTables& tables) {
    if (!mBound) {
        if (!mScene || !mKeys) throw InternalError("VisibilityPath::add: no scene");
        mRaster.setScene(*mScene, mTextureSets);
        mShade.setScene(*mScene, *mKeys, mTextureSets);
        mBound = true;
    }
    const std::span<const passes::DrawListItem> items = desc.list.ranges(passes::DrawRange::Opaque, passes::DrawRange::Masked);
    graph::RenderGraph& graph = *frame.graph;
    const shading::VisibilityFrame extent =
        passes::visibilityExtent(desc.size.width, desc.size.height, passes::visibilityTileSize(mContext.properties().deviceType),
                                 static_cast<uint32_t>(tables.lists.size()), desc.size.samples);
    std::vector<shading::VisibilityDraw> draws = tables.draws;
    if (draws.empty()) draws.emplace_back();  // a buffer is never empty
    const graph::BufferId drawBuffer = frame.addHostUpload("visibility_draws", bytesOf(draws));
    const graph::BufferId frameData = frame.addHostUpload("visibility_frame", bytesOf(std::vector{extent}));
    const passes::VisibilityTargets targets = mRaster.add(graph, desc.size, items, desc.keys, desc.inputs, desc.recorded);
    const passes::VisibilityTileLists tiles = mClassify.add(graph, targets.visibility, drawBuffer, frameData, extent);
    const graph::TextureId hdr = mShade.add(graph, {.visibility = targets.visibility,
                                                    .tiles = tiles,
                                                    .draws = drawBuffer,
                                                    .frameData = frameData,
                                                    .extent = extent,
                                                    .tables = &tables,
                                                    .frame = &desc.inputs});
    VisibilitySummary summary{.draws = static_cast<uint32_t>(items.size()),
                              .width = desc.size.width,
                              .height = desc.size.height,
                              .samples = desc.size.samples,
                              .tiles = extent.extent.w,
                              .tileWidth = extent.lists.z,
                              .tileHeight = extent.lists.w};
    for (const passes::ShadingList& list : tables.lists) summary.lists.push_back({list.variant.name(), list.textureSet, list.items});
    frame.visibility = std::move(summary);
    return passes::DrawTarget{.color = hdr, .depth = targets.depth, .hdr = hdr};
}

}  // namespace candela
