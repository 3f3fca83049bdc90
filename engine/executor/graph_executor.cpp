#include "executor/graph_executor.h"

#include "vk/commands.h"
#include "vk/context.h"

#include <algorithm>
#include <string>

namespace candela::graph {

void ImportBindings::bind(TextureId texture, VkImage image, VkImageView view, std::vector<VkImageView> mipViews) {
    mImages[texture.index] = {image, view, std::move(mipViews)};
}
void ImportBindings::bind(BufferId buffer, VkBuffer handle) { mBuffers[buffer.index] = handle; }

const ImportBindings::ImageBinding* ImportBindings::image(uint32_t resource) const {
    auto it = mImages.find(resource);
    return it == mImages.end() ? nullptr : &it->second;
}

VkBuffer ImportBindings::buffer(uint32_t resource) const {
    auto it = mBuffers.find(resource);
    return it == mBuffers.end() ? VK_NULL_HANDLE : it->second;
}

PassContext::PassContext(const RenderGraph& graph, uint32_t pass, const Bindings& bindings)
    : mGraph(&graph), mPassIndex(pass), mPass(&graph.declaration().passes.at(pass)), mBindings(bindings) {}

const AccessDecl& PassContext::declared(ResourceKind kind, uint32_t index, uint32_t version) const {
    return declaredAccess(mGraph->declaration(), mPassIndex, kind, index, version);
}

VkImage PassContext::image(TextureId texture) const {
    const uint32_t r = declared(ResourceKind::Texture, texture.index, texture.version).resource;
    if (mGraph->declaration().resources[r].imported) return mBindings.imports->image(r)->image;
    return mBindings.transients->image(r);
}

VkImageView PassContext::view(TextureId texture) const {
    const uint32_t r = declared(ResourceKind::Texture, texture.index, texture.version).resource;
    if (mGraph->declaration().resources[r].imported) return mBindings.imports->image(r)->view;
    return mBindings.transients->view(r);
}

VkImageView PassContext::mipView(TextureId texture, uint32_t mip) const {
    const uint32_t r = declared(ResourceKind::Texture, texture.index, texture.version).resource;
    const ResourceDecl& resource = mGraph->declaration().resources[r];
    VkImageView view = VK_NULL_HANDLE;
    if (mip < resource.texture.mipLevels) {
        if (!resource.imported) {
            view = mBindings.transients->mipView(r, mip);
        } else if (const auto& views = mBindings.imports->image(r)->mipViews; mip < views.size()) {
            view = views[mip];
        }
    }
    if (view == VK_NULL_HANDLE) {
        const bool inRange = mip < resource.texture.mipLevels;
        throw GraphError(std::string("pass '") + passName() + "' asks for mip " + std::to_string(mip) + " of '" +
                         resource.name + "', which has " + std::to_string(resource.texture.mipLevels) + " mips" +
                         (!inRange ? ""
                          : resource.imported ? " but no view of it was bound"
                                              : " but no per-mip views (transients get them with storage usage)"));
    }
    return view;
}

VkImageLayout PassContext::layout(TextureId texture) const {
    const uint32_t r = declared(ResourceKind::Texture, texture.index, texture.version).resource;
    return passAccessState(mGraph->declaration(), *mPass, r).layout;
}

VkBuffer PassContext::buffer(BufferId buffer) const {
    const uint32_t r = declared(ResourceKind::Buffer, buffer.index, buffer.version).resource;
    if (mGraph->declaration().resources[r].imported) return mBindings.imports->buffer(r);
    return mBindings.transients->buffer(r);
}

const TextureDesc& PassContext::desc(TextureId texture) const {
    return mGraph->declaration().resources[declared(ResourceKind::Texture, texture.index, texture.version).resource].texture;
}

const BufferDesc& PassContext::desc(BufferId buffer) const {
    return mGraph->declaration().resources[declared(ResourceKind::Buffer, buffer.index, buffer.version).resource].buffer;
}

VkExtent2D PassContext::extent(TextureId texture) const {
    const TextureDesc& d = desc(texture);
    return {d.width, d.height};
}

std::optional<VkClearValue> PassContext::lostContentsClear(TextureId written) const {
    const PassInfo& info = mGraph->compiled().passes[mPassIndex];
    for (const AccessDecl& a : mPass->writes)
        if (a.resource == written.index && a.version == written.version && a.clearIfLost &&
            std::find(info.clearedLostInputs.begin(), info.clearedLostInputs.end(), a.resource) !=
                info.clearedLostInputs.end())
            return a.clearIfLost;
    return std::nullopt;
}

void PassContext::beginRendering() const {
    const PassInfo& planned = mGraph->compiled().passes[mPassIndex];
    std::vector<VkRenderingAttachmentInfo> colors;
    std::vector<uint32_t> colorResources;  // the resource of each of `colors`
    VkRenderingAttachmentInfo depth{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    bool hasDepth = false;
    VkExtent2D extent{0, 0};
    // Load and store operations as the graph's "attachments" step planned them: a result no later
    // pass reads is not stored (a multisampled attachment then never leaves tile memory on GPUs
    // that have it), and nothing is loaded that no earlier pass wrote.
    const auto attachment = [&](const AccessDecl& a, VkImageLayout layout) {
        const TextureId id{a.resource, a.version};
        if (extent.width == 0) extent = this->extent(id);
        const AttachmentOps* ops = planned.attachmentOps(a.resource);
        if (!ops) throw GraphError(std::string("pass '") + passName() + "' has no planned attachment operations for '" +
                                   mGraph->declaration().resources[a.resource].name + "'");
        VkRenderingAttachmentInfo info{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                       .imageView = view(id),
                                       .imageLayout = layout};
        switch (ops->load) {
            case LoadOp::Load: info.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD; break;
            case LoadOp::Clear: info.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR; info.clearValue = ops->clear; break;
            case LoadOp::DontCare: info.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE; break;
        }
        switch (ops->store) {
            case StoreOp::Store: info.storeOp = VK_ATTACHMENT_STORE_OP_STORE; break;
            case StoreOp::DontCare: info.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE; break;
            case StoreOp::None: info.storeOp = VK_ATTACHMENT_STORE_OP_NONE; break;
        }
        return info;
    };
    for (const AccessDecl& a : mPass->writes) {
        if (a.usage == Usage::ColorAttachment) {
            colors.push_back(attachment(a, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL));
            colorResources.push_back(a.resource);
        }
        if (a.usage == Usage::DepthAttachment) {
            depth = attachment(a, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
            hasDepth = true;
        }
    }
    // Resolves into the single-sample images, skipped where a later pass resolves over the result.
    for (const AccessDecl& a : mPass->writes) {
        if (a.usage != Usage::ResolveAttachment || planned.writeUnread(a.resource)) continue;
        const size_t c = size_t(std::find(colorResources.begin(), colorResources.end(), a.resolveSource) - colorResources.begin());
        colors[c].resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;  // validation made sure the source is one of them
        colors[c].resolveImageView = view({a.resource, a.version});
        colors[c].resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    for (const AccessDecl& a : mPass->reads)
        if (a.usage == Usage::DepthRead) {
            depth = attachment(a, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL);
            hasDepth = true;
        }
    const VkRenderingInfo info{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                               .renderArea = {{0, 0}, extent},
                               .layerCount = 1,
                               .colorAttachmentCount = static_cast<uint32_t>(colors.size()),
                               .pColorAttachments = colors.data(),
                               .pDepthAttachment = hasDepth ? &depth : nullptr};
    vkCmdBeginRendering(mBindings.cmd, &info);
    vk::setViewportAndScissor(mBindings.cmd, extent);
}

void PassContext::endRendering() const { vkCmdEndRendering(mBindings.cmd); }

namespace {

struct BarrierBatch {
    std::vector<VkImageMemoryBarrier2> images;
    std::vector<VkBufferMemoryBarrier2> buffers;

    void add(const ExecuteInputs& in, const Barrier& b) {
        const ResourceDecl& r = in.graph.declaration().resources[b.resource];
        if (r.kind == ResourceKind::Texture) {
            const auto* imported = r.imported ? in.imports.image(b.resource) : nullptr;
            images.push_back({.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
                              .srcStageMask = b.src.stages,
                              .srcAccessMask = b.src.access,
                              .dstStageMask = b.dst.stages,
                              .dstAccessMask = b.dst.access,
                              .oldLayout = b.src.layout,
                              .newLayout = b.dst.layout,
                              .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                              .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                              .image = imported ? imported->image : in.transients.image(b.resource),
                              .subresourceRange = {vk::aspectOf(r.texture.format), 0, VK_REMAINING_MIP_LEVELS, 0,
                                                   VK_REMAINING_ARRAY_LAYERS}});
        } else {
            buffers.push_back({.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2,
                               .srcStageMask = b.src.stages,
                               .srcAccessMask = b.src.access,
                               .dstStageMask = b.dst.stages,
                               .dstAccessMask = b.dst.access,
                               .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                               .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                               .buffer = r.imported ? in.imports.buffer(b.resource) : in.transients.buffer(b.resource),
                               .offset = 0,
                               .size = VK_WHOLE_SIZE});
        }
    }

    void emit(VkCommandBuffer cmd) const {
        if (images.empty() && buffers.empty()) return;
        const VkDependencyInfo dependency{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                          .bufferMemoryBarrierCount = static_cast<uint32_t>(buffers.size()),
                                          .pBufferMemoryBarriers = buffers.data(),
                                          .imageMemoryBarrierCount = static_cast<uint32_t>(images.size()),
                                          .pImageMemoryBarriers = images.data()};
        vkCmdPipelineBarrier2(cmd, &dependency);
    }
};

void emitBarriers(const ExecuteInputs& in, const std::vector<Barrier>& barriers) {
    if (!in.emitBarriers) return;
    BarrierBatch batch;
    for (const Barrier& b : barriers) batch.add(in, b);
    batch.emit(in.cmd);
}

}  // namespace

ExecutionRecord executeGraph(const ExecuteInputs& in) {
    if (!in.graph.isCompiled()) throw GraphError("executeGraph: the graph was not compiled");
    const GraphDecl& decl = in.graph.declaration();
    const CompiledGraph& compiled = in.graph.compiled();
    for (uint32_t r = 0; r < decl.resources.size(); ++r) {
        const ResourceDecl& res = decl.resources[r];
        if (!res.imported || !compiled.lifetimes[r].used()) continue;
        const bool bound = res.kind == ResourceKind::Texture ? in.imports.image(r) != nullptr
                                                             : in.imports.buffer(r) != VK_NULL_HANDLE;
        if (!bound) throw GraphError("imported resource '" + res.name + "' has no Vulkan object bound");
    }

    ExecutionRecord record;
    record.passCount = static_cast<uint32_t>(decl.passes.size());
    const PassContext::Bindings bindings{.context = &in.context,
                                         .imports = &in.imports,
                                         .transients = &in.transients,
                                         .descriptors = &in.descriptors,
                                         .cmd = in.cmd};
    for (size_t i = 0; i < compiled.order.size(); ++i) {
        const uint32_t pass = compiled.order[i];
        PassContext ctx(in.graph, pass, bindings);
        emitBarriers(in, compiled.barriers[i]);
        in.context.beginLabel(in.cmd, ctx.passName());
        const auto begin = in.timestamps ? in.timestamps->write(in.cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT) : std::nullopt;
        if (const ExecuteFn& fn = in.graph.callback(pass)) fn(ctx);
        // Once every earlier command has completed (bottom of pipe in a timestamp's first scope).
        const auto end = in.timestamps ? in.timestamps->write(in.cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT) : std::nullopt;
        if (begin && end) record.queries.push_back({pass, {*begin, *end}});
        in.context.endLabel(in.cmd);
        if (in.afterPass) in.afterPass(pass);
    }
    emitBarriers(in, compiled.finalBarriers);
    return record;
}

GraphTimings ExecutionRecord::timings(vk::TimestampPool& timestamps) const {
    GraphTimings out;
    out.gpuMs.assign(passCount, -1.0);
    out.gpuMsUnreliable = !timestamps.measuresPasses();
    for (const auto& [pass, range] : queries) out.gpuMs[pass] = timestamps.elapsedMs(range.first, range.second);
    return out;
}

}  // namespace candela::graph
