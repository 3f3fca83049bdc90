#include "passes/drawing/draw_target.h"

namespace candela::passes {

using namespace graph;

DrawTarget createDrawTarget(PassBuilder& builder, const DrawTargetSize& size) {
    const TextureDesc hdr{.width = size.width, .height = size.height, .format = kHdrFormat};
    TextureDesc depth = hdr;
    depth.format = kDepthFormat;
    depth.samples = size.samples;
    DrawTarget target;
    target.hdr = builder.createTexture("hdr", hdr);
    target.depth = builder.createTexture("depth", depth);
    if (size.samples > 1) {
        TextureDesc color = hdr;
        color.samples = size.samples;
        target.color = builder.createTexture("hdr_msaa", color);
    } else {
        target.color = target.hdr;
    }
    return target;
}

DrawTarget drawInto(PassBuilder& builder, const DrawTarget& target, bool clear, DepthUse depth) {
    const bool multisampled = !(target.color == target.hdr);
    DrawTarget out;
    out.color = builder.writeColor(target.color, clear ? std::optional(VkClearColorValue{{0.0f, 0.0f, 0.0f, 0.0f}})
                                                       : std::nullopt);
    switch (depth) {
        case DepthUse::Clear: out.depth = builder.writeDepth(target.depth, 0.0f); break;  // reverse-Z: far = 0
        case DepthUse::Write: out.depth = builder.writeDepth(target.depth, std::nullopt); break;
        case DepthUse::Test: out.depth = builder.read(target.depth, Usage::DepthRead); break;
    }
    out.hdr = multisampled ? builder.resolve(out.color, target.hdr) : out.color;
    return out;
}

uint32_t samplesOf(const PassBuilder& builder, const DrawTarget& target) { return builder.desc(target.color).samples; }

}  // namespace candela::passes
