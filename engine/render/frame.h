#pragma once
// One frame as built and what a completed frame tells: the frame's graph with the Vulkan objects
// bound to its imported resources, the handles of its results, the data the CPU writes for it, and
// what `--explain` says of it; the presentable image it may render into; its timings.

#include "executor/graph_executor.h"
#include "graph/render_graph.h"
#include "passes/aov/aov_pass.h"
#include "passes/drawing/shading_summary.h"
#include "render/frame_plan.h"
#include "render/posed_summary.h"
#include "render/visibility_summary.h"

#include <chrono>
#include <cstring>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace candela {

// A frame's graph and what goes with it. FrameBuilder declares the passes; the caller adds the
// ending (readback, overlay, export); FrameRunner compiles, records and submits it, then keeps it
// as the last frame (for export, --explain and finishing the IBL precompute).
struct Frame {
    std::unique_ptr<graph::RenderGraph> graph = std::make_unique<graph::RenderGraph>();
    graph::ImportBindings imports;
    graph::TextureId hdr;  // linear HDR (RGBA16F): the scene after forward and skybox, or the test pattern
    graph::TextureId ldr;  // the 8-bit image: tonemapped scene, or encoded pattern
    // The aov pass's targets when the frame asks for per-pixel outputs besides colour.
    std::optional<passes::AovTargets> aov;
    // The IBL precompute passes added: declared pass indices [precomputeBegin, precomputeEnd).
    uint32_t precomputeBegin = 0, precomputeEnd = 0;
    // The declared index of the pass computing the sheen LUT (ibl_maps::SheenLut), if the frame added it.
    uint32_t sheenLutPass = graph::kInvalidIndex;
    // A scene frame's plan (what it draws and where, what it leaves out and why); none for a test
    // pattern or a calibration frame.
    std::optional<FramePlan> plan;
    // What a scene frame's draws asked of the shading programs (variants, what the scene leaves
    // out); none for other frames.
    std::optional<passes::ShadingSummary> shading;
    // What a visibility-path frame's raster, classification and shading did; none for other frames.
    std::optional<VisibilitySummary> visibility;
    // What a scene frame's pose animates besides its nodes (empty: nothing, or no scene frame).
    PosedSummary posed;
    // Whether the tonemap put a solid background colour behind the scene (under a skybox pass's
    // sky, if one ran, it is not seen).
    bool solidBackground = false;
    // What --explain says of the frame (variants, lights, IBL, what was left out), besides culled passes.
    std::vector<std::string> explanation;
    // Data the CPU makes for this frame alone (the posed draws of an animated scene): each is
    // copied, once the frame slot is free, into that slot's own host-visible buffer
    // (vk::HostUploadRing), which is then bound to the imported handle.
    struct HostUpload {
        graph::BufferId buffer;
        std::vector<std::byte> bytes;
    };
    std::vector<HostUpload> hostUploads;
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();

    // Declares `bytes` as a storage buffer the CPU writes for this frame (nothing on the device
    // wrote it before the frame: no barrier to wait for).
    graph::BufferId addHostUpload(std::string name, std::vector<std::byte> bytes);
    // Whether the IBL precompute passes were added to this frame.
    bool precomputes() const { return precomputeBegin != precomputeEnd; }
    // Whether a pass filling persistent maps runs in this frame: one of the IBL precompute passes
    // (BRDF LUT included) or the sheen LUT pass. Their owners (ibl_maps::IblMaps, ibl_maps::SheenLut) take the
    // results over only once told the frame completed (SceneState::frameCompleted), so the Renderer
    // waits for such a frame before building the next. Precondition: the graph was compiled.
    bool computesMaps() const;
};

// The bytes of `items`, for a host upload (an empty vector gives no bytes).
template <typename T>
std::vector<std::byte> bytesOf(const std::vector<T>& items) {
    std::vector<std::byte> out(items.size() * sizeof(T));
    if (!out.empty()) std::memcpy(out.data(), items.data(), out.size());
    return out;
}

// A presentable image to render into (a vk::Swapchain image, or an offscreen stand-in for one):
// the tonemap writes it, the overlay draws over it, and it ends in `finalLayout`. The frame waits
// on `acquired` (if not null) before writing it and signals `rendered` (if not null) when done.
struct PresentTarget {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkSemaphore acquired = VK_NULL_HANDLE;
    VkSemaphore rendered = VK_NULL_HANDLE;
    // PRESENT_SRC_KHR for a swapchain image; an offscreen target (`bench --in-flight`) names
    // another (a device without VK_KHR_swapchain has no PRESENT_SRC_KHR).
    VkImageLayout finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
};

// GPU time of one pass of a completed frame.
struct PassTime {
    std::string name;
    double gpuMs = -1.0;  // negative: the pass did not run or was not measured
};

struct FrameTiming {
    double cpuMs = 0.0;           // CPU wall time to build, compile and record the frame and submit it
    double submitWaitMs = 0.0;    // CPU wall time from submit to the fence
    graph::GraphTimings timings;  // per declared pass of that frame's graph
};

// The last IBL precompute: the frame that ran it, from the start of its building to its fence, and
// the GPU time of its precompute passes. Negative before any.
struct PrecomputeTime {
    double frameMs = -1.0;
    double gpuMs = -1.0;
};

}  // namespace candela
