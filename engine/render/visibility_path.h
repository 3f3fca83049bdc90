#pragma once
// VisibilityPath: the visibility shading path of a scene frame (docs/shading-paths.md) — the
// visibility pass (draw list → depth and per-pixel IDs), classification (tiles → per-list tile
// lists and indirect arguments) and compute shading (each covered pixel once) —
// and whether a frame can take it. FrameBuilder adds it instead of the forward pass's opaque draws;
// the blended and transmissive draws follow on the forward pass either way.

#include "options/shading_path.h"
#include "passes/visibility/visibility_classify_pass.h"
#include "passes/visibility/visibility_texture_sets.h"
#include "passes/visibility/visibility_pass.h"
#include "passes/visibility/visibility_shade_pass.h"
#include "render/frame.h"

#include <optional>
#include <string>

namespace candela {

// The path `--shading-path auto` takes on `context`'s device, and why (for `candela info` and
// --explain; docs/shading-paths.md, "Choosing the default").
std::pair<options::ShadingPath, std::string> defaultShadingPath(const vk::Context& context);

class VisibilityPath {
public:
    explicit VisibilityPath(vk::Context& context);

    // Takes the scene, or records why it cannot take the path (unsupported()). The path's passes
    // bind it (their pipelines, programs and descriptor sets) at its first frame on this path, so a
    // scene drawn on the forward path builds none of them. Preconditions: the GPU no longer uses the
    // previous scene's sets; `scene` and `keys` outlive their use.
    void setScene(const gpu_scene::GpuScene& scene, const passes::MaterialKeys& keys);
    // Why frames of the current scene cannot take the path ("" if they can): the device's reason,
    // or the scene's (its vertices or indices past maxStorageBufferRange).
    const std::string& unsupported() const { return mUnsupported; }
    // Whether the device samples integer images (the visibility image) at `samples` samples.
    bool samplesIntegerImages(uint32_t samples) const;

    struct FrameDesc {
        passes::DrawTargetSize size;
        const passes::DrawList& list;
        const passes::MaterialKeys& keys;
        const passes::FrameInputs& inputs;
        passes::DrawStats* recorded = nullptr;
    };
    // The frame's visibility tables (its shading lists and draw entries) for the list's opaque and
    // masked draws; nullopt when the frame needs more shading lists than a tile's mask holds.
    std::optional<passes::VisibilityFrameTables> tables(const FrameDesc& desc) const;
    // Adds the path's passes for the list's opaque and masked draws with their `tables`: the shaded
    // image (transparent behind) and the depth, as targets the forward and skybox passes can draw
    // over. Sets frame.visibility to what the path did (render/visibility_summary.h).
    passes::DrawTarget add(Frame& frame, const FrameDesc& desc, const passes::VisibilityFrameTables& tables);

private:
    vk::Context& mContext;
    passes::VisibilityPass mRaster;
    passes::VisibilityClassifyPass mClassify;
    passes::VisibilityShadePass mShade;
    passes::TextureSets mTextureSets;
    std::string mUnsupported;
    // The scene setScene took, until the passes bind it (add).
    const gpu_scene::GpuScene* mScene = nullptr;
    const passes::MaterialKeys* mKeys = nullptr;
    bool mBound = false;
};

}  // namespace candela
