#pragma once
// A workaround for devices whose DeviceChoices::cubeBordersNeedADraw (SwiftShader): a cube map
// written by compute shaders is bound to one draw, which rasterizes nothing, before compute shaders
// filter it. SwiftShader keeps a one-texel border around each face for seamless filtering and
// refreshes the borders only when a draw is about to sample the image; a compute shader filtering
// across a face edge otherwise reads stale borders (docs/devices.md). Recorded by ibl_cubemap after
// it writes the environment's float cube, which the prefilter, SH and irradiance passes filter in
// compute; the other cubes are filtered in compute only by the visibility path's shading, which
// SwiftShader cannot run (no geometryShader), and by draws otherwise, which refresh them. On every
// other device nothing is recorded or built.

#include "executor/graph_executor.h"
#include "vk/pipeline.h"
#include "vk/sampler.h"

namespace candela::passes {

class CubeBorderDraw {
public:
    // Builds the vertex-only pipeline (shaders/ibl/cube_borders.glsl) when the device needs it.
    explicit CubeBorderDraw(vk::Context& context);

    // On a device that needs it, records: a barrier making the compute writes of the pass visible
    // to the vertex stage, one point drawn with rasterizer discard and the cube `view` (in `layout`,
    // as the pass holds it) bound, and a barrier ordering that draw before later compute work (the
    // graph's barriers after the pass continue from the compute stage). Preconditions: inside a
    // compute pass that wrote the cube, outside any rendering.
    void record(const graph::PassContext& ctx, VkImageView view, VkImageLayout layout) const;

private:
    vk::Pipeline mPipeline;  // empty when the device does not need the draw
    vk::Sampler mSampler;
};

}  // namespace candela::passes
