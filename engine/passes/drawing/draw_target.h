#pragma once
// The targets the scene's draw passes ("forward", "skybox", "forward_transmission") draw into:
// HDR colour (RGBA16F, premultiplied, alpha = coverage) and reverse-Z depth at the frame's sample
// count and, with MSAA, the single-sample HDR image each of them resolves into at the end of its
// render pass (a render-pass resolve, no copy), which the later passes read. The graph skips the
// resolves a later draw pass resolves over and stores no attachment nothing reads, so with the
// skybox last only its resolve runs (PassInfo::unreadWrites).

#include "graph/render_graph.h"

#include <cstdint>

namespace candela::passes {

struct DrawTargetSize {
    uint32_t width = 1;
    uint32_t height = 1;
    uint32_t samples = 1;  // 1, 2, 4 or 8: MSAA when > 1
};

struct DrawTarget {
    graph::TextureId color;  // the colour attachment drawn into: "hdr" at 1 sample, else "hdr_msaa"
    graph::TextureId depth;  // "depth", at the same sample count
    graph::TextureId hdr;    // single-sample "hdr", what later passes read (== color at 1 sample)
};

inline constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

// Creates the targets as transients of the graph (no contents yet).
DrawTarget createDrawTarget(graph::PassBuilder& builder, const DrawTargetSize& size);

enum class DepthUse : uint8_t {
    Clear,  // cleared to far (0, reverse-Z), then tested and written
    Write,  // loaded, tested and written
    Test,   // loaded and tested only (read-only layout)
};

// Declares the calling pass's draws into `target`: its colour cleared to transparent black
// (`clear`) or loaded, its depth as `depth` says and, with MSAA, the resolve into target.hdr.
// Returns the versions the pass writes (depth unchanged for DepthUse::Test).
DrawTarget drawInto(graph::PassBuilder& builder, const DrawTarget& target, bool clear, DepthUse depth);

// The sample count of the targets (1 without MSAA).
uint32_t samplesOf(const graph::PassBuilder& builder, const DrawTarget& target);

}  // namespace candela::passes
