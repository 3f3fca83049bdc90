#include "renderer.h"

#include "core/check.h"
#include "passes/readback_pass.h"
#include "vk/context.h"

#include <glm/gtc/packing.hpp>

#include <chrono>
#include <cstring>

namespace candela {

using namespace graph;

namespace {
constexpr VkFormat kLdrFormat = VK_FORMAT_R8G8B8A8_SRGB;

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

Renderer::Renderer(vk::Context& context, uint32_t framesInFlight)
    : mContext(context), mFrames(context, framesInFlight), mPattern(context), mEncode(context, kLdrFormat),
      mGraph(std::make_unique<RenderGraph>()) {
    for (uint32_t i = 0; i < mFrames.slotCount(); ++i) mTransients.push_back(std::make_unique<TransientPool>(context));
}

Renderer::~Renderer() { mFrames.waitIdle(); }

void Renderer::validateSettings(const RenderSettings& settings) const {
    const uint32_t limit = mContext.properties().limits.maxImageDimension2D;
    if (settings.width == 0 || settings.height == 0)
        throw UserError("image size must be at least 1x1 (got " + std::to_string(settings.width) + "x" +
                        std::to_string(settings.height) + ")");
    if (settings.width > limit || settings.height > limit)
        throw UserError("image size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                        " exceeds the device limit of " + std::to_string(limit) + " pixels per side");
}

uint32_t Renderer::transientRebuilds() const {
    uint32_t total = 0;
    for (const auto& pool : mTransients) total += pool->rebuilds();
    return total;
}

CapturedFrame Renderer::capture(const RenderSettings& settings) {
    validateSettings(settings);
    const VkDeviceSize texel = settings.floatOutput ? 8 : 4;  // RGBA16F or RGBA8
    const VkDeviceSize bytes = texel * settings.width * settings.height;
    if (!mReadback || mReadback.size() != bytes)
        mReadback = vk::Buffer(mContext, {.size = bytes,
                                          .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                          .memory = vk::MemoryUsage::Readback,
                                          .name = "readback"});

    vk::FrameSlot& slot = mFrames.begin();
    mGraph = std::make_unique<RenderGraph>();
    RenderGraph& graph = *mGraph;
    const BufferId readback =
        graph.importBuffer("readback", {.size = bytes}, ResourceState{}, passes::hostReadState());
    const TextureId hdr = mPattern.add(graph, settings.width, settings.height, settings.exposure);
    const TextureId ldr = graph.createTexture("ldr", {.width = settings.width, .height = settings.height, .format = kLdrFormat});
    const TextureId encoded = mEncode.add(graph, hdr, ldr);
    passes::addReadbackPass(graph, settings.floatOutput ? hdr : encoded, readback);
    for (const std::string& name : settings.disabledPasses) {
        if (!graph.findPass(name)) {
            std::string names;
            for (const PassDecl& p : graph.declaration().passes) names += (names.empty() ? "" : ", ") + p.name;
            throw UserError("cannot disable pass '" + name + "': no such pass (passes: " + names + ")");
        }
        graph.setPassEnabled(name, false);
    }

    graph.compile({.memoryRequirements = deviceMemoryRequirements(mContext, graph.declaration())});
    TransientPool& transients = *mTransients[mFrames.currentSlot()];
    transients.realize(graph.declaration(), graph.compiled());
    ImportBindings imports;
    imports.bind(readback, mReadback.handle());
    const ExecutionRecord record = executeGraph({.context = mContext,
                                                 .graph = graph,
                                                 .imports = imports,
                                                 .transients = transients,
                                                 .cmd = slot.cmd,
                                                 .descriptors = *slot.descriptors,
                                                 .timestamps = slot.timestamps.get(),
                                                 .emitBarriers = settings.emitBarriers});

    CapturedFrame frame;
    frame.width = settings.width;
    frame.height = settings.height;
    const auto submitted = std::chrono::steady_clock::now();
    mFrames.submit();
    mFrames.waitCurrent();
    frame.submitWaitMs = msSince(submitted);
    frame.timings = record.timings(*slot.timestamps);

    const bool producedOutput = graph.compiled().passes[*graph.findPass("readback")].cullReason == CullReason::None;
    if (!producedOutput) throw UserError("nothing to capture: the readback pass was culled (" +
                                         graph.compiled().passes[*graph.findPass("readback")].cullDetail + ")");
    const auto readStart = std::chrono::steady_clock::now();
    mReadback.invalidate();
    const size_t texels = static_cast<size_t>(settings.width) * settings.height;
    if (settings.floatOutput) {
        frame.rgba32f.resize(texels * 4);
        const auto* half = reinterpret_cast<const uint16_t*>(mReadback.mapped());
        for (size_t i = 0; i < texels * 4; ++i) frame.rgba32f[i] = glm::unpackHalf1x16(half[i]);
    } else {
        frame.rgba8.resize(texels * 4);
        std::memcpy(frame.rgba8.data(), mReadback.mapped(), frame.rgba8.size());
    }
    frame.readbackMs = msSince(readStart);
    return frame;
}

}  // namespace candela
