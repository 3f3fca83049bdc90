// RenderGraph and PassBuilder: record the declaration (GraphDecl) and hand it to compileGraph().

#include "graph/render_graph.h"

#include "graph/compile_steps.h"

#include <algorithm>

namespace candela::graph {

using detail::quotedName;

namespace {

const char* kindName(ResourceKind kind) { return kind == ResourceKind::Texture ? "texture" : "buffer"; }

// Checks that (kind, index, version) names an existing version of an existing resource.
// `what` describes the use for the message, e.g. "pass 'tonemap' reads".
const ResourceDecl& checkHandle(const GraphDecl& decl, const std::string& what, ResourceKind kind,
                                uint32_t index, uint32_t version) {
    if (index >= decl.resources.size())
        throw GraphError(what + " an invalid " + kindName(kind) + " handle (index " +
                         (index == kInvalidIndex ? std::string("none") : std::to_string(index)) + ")");
    const ResourceDecl& resource = decl.resources[index];
    if (resource.kind != kind)
        throw GraphError(what + " " + quotedName(resource.name) + " through a " + kindName(kind) +
                         " handle, but it is a " + kindName(resource.kind));
    if (version >= resource.versionCount)
        throw GraphError(what + " " + quotedName(resource.name) + " (version " + std::to_string(version) +
                         "), which does not exist yet (latest is " +
                         std::to_string(resource.versionCount - 1) + ")");
    return resource;
}

// A transfer pass only copies: refuse usages that need shaders, attachments or vertex input,
// whose stages it does not have.
void checkTransferUsage(const PassDecl& pass, const std::string& what, const ResourceDecl& resource, Usage usage) {
    if (pass.type != PassType::Transfer || usage == Usage::TransferSrc || usage == Usage::TransferDst) return;
    throw GraphError(what + " " + quotedName(resource.name) + " with usage " + usageName(usage) +
                     ", but it is a transfer pass (TransferSrc and TransferDst only)");
}

ResourceDecl makeTexture(std::string name, const TextureDesc& desc) {
    ResourceDecl resource;
    resource.name = std::move(name);
    resource.kind = ResourceKind::Texture;
    resource.texture = desc;
    return resource;
}

ResourceDecl makeBuffer(std::string name, const BufferDesc& desc) {
    ResourceDecl resource;
    resource.name = std::move(name);
    resource.kind = ResourceKind::Buffer;
    resource.buffer = desc;
    return resource;
}

}  // namespace

TextureId PassBuilder::createTexture(std::string name, const TextureDesc& desc) {
    return {mGraph.addResource(makeTexture(std::move(name), desc)), 0};
}

BufferId PassBuilder::createBuffer(std::string name, const BufferDesc& desc) {
    return {mGraph.addResource(makeBuffer(std::move(name), desc)), 0};
}

TextureId PassBuilder::read(TextureId texture, Usage usage, VkPipelineStageFlags2 stageOverride) {
    mGraph.addRead(mPass, ResourceKind::Texture, texture.index, texture.version, usage, stageOverride);
    return texture;
}

BufferId PassBuilder::read(BufferId buffer, Usage usage, VkPipelineStageFlags2 stageOverride) {
    mGraph.addRead(mPass, ResourceKind::Buffer, buffer.index, buffer.version, usage, stageOverride);
    return buffer;
}

TextureId PassBuilder::sample(TextureId texture) {
    const PassType type = mGraph.mDecl.passes[mPass].type;
    return read(texture, Usage::Sampled, type == PassType::Graphics ? VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT : 0);
}

const TextureDesc& PassBuilder::desc(TextureId texture) const {
    const std::string what = "pass " + quotedName(mGraph.mDecl.passes[mPass].name) + " asks for the description of";
    return checkHandle(mGraph.mDecl, what, ResourceKind::Texture, texture.index, texture.version).texture;
}

const BufferDesc& PassBuilder::desc(BufferId buffer) const {
    const std::string what = "pass " + quotedName(mGraph.mDecl.passes[mPass].name) + " asks for the description of";
    return checkHandle(mGraph.mDecl, what, ResourceKind::Buffer, buffer.index, buffer.version).buffer;
}

TextureId PassBuilder::write(TextureId texture, Usage usage, WriteMode mode,
                             VkPipelineStageFlags2 stageOverride) {
    const AccessDecl& access = mGraph.addWrite(mPass, ResourceKind::Texture, texture.index,
                                               texture.version, usage, mode, stageOverride);
    return {texture.index, access.version};
}

BufferId PassBuilder::write(BufferId buffer, Usage usage, WriteMode mode, VkPipelineStageFlags2 stageOverride) {
    const AccessDecl& access = mGraph.addWrite(mPass, ResourceKind::Buffer, buffer.index, buffer.version,
                                               usage, mode, stageOverride);
    return {buffer.index, access.version};
}

TextureId PassBuilder::writeColor(TextureId texture, std::optional<VkClearColorValue> clear) {
    AccessDecl& access = mGraph.addWrite(mPass, ResourceKind::Texture, texture.index, texture.version,
                                         Usage::ColorAttachment,
                                         clear ? WriteMode::Discard : WriteMode::Preserve, 0);
    if (clear) {
        VkClearValue value{};
        value.color = *clear;
        access.clear = value;
    }
    return {texture.index, access.version};
}

TextureId PassBuilder::drawOver(TextureId texture, VkClearColorValue fallback) {
    AccessDecl& access = mGraph.addWrite(mPass, ResourceKind::Texture, texture.index, texture.version,
                                         Usage::ColorAttachment, WriteMode::Preserve, 0);
    VkClearValue value{};
    value.color = fallback;
    access.clearIfLost = value;
    return {texture.index, access.version};
}

TextureId PassBuilder::writeDepth(TextureId texture, std::optional<float> clearDepth) {
    AccessDecl& access = mGraph.addWrite(mPass, ResourceKind::Texture, texture.index, texture.version,
                                         Usage::DepthAttachment,
                                         clearDepth ? WriteMode::Discard : WriteMode::Preserve, 0);
    if (clearDepth) {
        VkClearValue value{};
        value.depthStencil = {*clearDepth, 0};
        access.clear = value;
    }
    return {texture.index, access.version};
}

TextureId PassBuilder::resolve(TextureId multisampled, TextureId target) {
    const PassDecl& pass = mGraph.mDecl.passes[mPass];
    const std::string what = "pass " + quotedName(pass.name) + " resolves";
    const ResourceDecl& source = checkHandle(mGraph.mDecl, what, ResourceKind::Texture, multisampled.index, multisampled.version);
    const ResourceDecl& into = checkHandle(mGraph.mDecl, what + " into", ResourceKind::Texture, target.index, target.version);
    const auto colorWrite = std::find_if(pass.writes.begin(), pass.writes.end(), [&](const AccessDecl& a) {
        return a.resource == multisampled.index && a.version == multisampled.version && a.usage == Usage::ColorAttachment;
    });
    if (colorWrite == pass.writes.end())
        throw GraphError(what + " " + quotedName(source.name) + ", which is not a colour attachment it writes (writeColor first)");
    if (source.texture.samples < 2)
        throw GraphError(what + " " + quotedName(source.name) + ", which has 1 sample (nothing to resolve)");
    if (into.texture.samples != 1 || into.texture.width != source.texture.width ||
        into.texture.height != source.texture.height || into.texture.format != source.texture.format)
        throw GraphError(what + " " + quotedName(source.name) + " into " + quotedName(into.name) +
                         ", which is not a single-sample image of its size and format");
    const WriteMode mode = colorWrite->mode;
    const uint32_t sourceIndex = multisampled.index;
    AccessDecl& access =
        mGraph.addWrite(mPass, ResourceKind::Texture, target.index, target.version, Usage::ResolveAttachment, mode, 0);
    access.resolveSource = sourceIndex;
    return {target.index, access.version};
}

void PassBuilder::sideEffect() { mGraph.mDecl.passes[mPass].sideEffect = true; }
void PassBuilder::cannotBeDisabled(std::string why) { mGraph.mDecl.passes[mPass].cannotBeDisabled = std::move(why); }

TextureId RenderGraph::importTexture(std::string name, const TextureDesc& desc, const ResourceState& initial,
                                     std::optional<ResourceState> final) {
    ResourceDecl resource = makeTexture(std::move(name), desc);
    resource.imported = true;
    resource.initialState = initial;
    resource.finalState = final;
    return {addResource(std::move(resource)), 0};
}

BufferId RenderGraph::importBuffer(std::string name, const BufferDesc& desc, const ResourceState& initial,
                                   std::optional<ResourceState> final) {
    ResourceDecl resource = makeBuffer(std::move(name), desc);
    resource.imported = true;
    resource.initialState = initial;
    resource.finalState = final;
    return {addResource(std::move(resource)), 0};
}

TextureId RenderGraph::createTexture(std::string name, const TextureDesc& desc) {
    return {addResource(makeTexture(std::move(name), desc)), 0};
}

BufferId RenderGraph::createBuffer(std::string name, const BufferDesc& desc) {
    return {addResource(makeBuffer(std::move(name), desc)), 0};
}

void RenderGraph::exportTexture(TextureId texture, std::optional<ResourceState> final) {
    checkHandle(mDecl, "exportTexture received", ResourceKind::Texture, texture.index, texture.version);
    mDecl.resources[texture.index].exported = true;
    if (final) mDecl.resources[texture.index].finalState = final;
}

void RenderGraph::exportBuffer(BufferId buffer, std::optional<ResourceState> final) {
    checkHandle(mDecl, "exportBuffer received", ResourceKind::Buffer, buffer.index, buffer.version);
    mDecl.resources[buffer.index].exported = true;
    if (final) mDecl.resources[buffer.index].finalState = final;
}

void RenderGraph::setPassEnabled(std::string_view name, bool enabled) {
    bool found = false;
    for (PassDecl& pass : mDecl.passes) {
        if (pass.name != name) continue;
        pass.enabled = enabled;
        found = true;
    }
    if (!found) throw GraphError("setPassEnabled: no pass named " + quotedName(std::string(name)));
}

const CompiledGraph& RenderGraph::compile(const CompileOptions& options) {
    // A failed compile must not leave the previous result looking current.
    mIsCompiled = false;
    mCompiled = compileGraph(mDecl, options);
    mIsCompiled = true;
    return mCompiled;
}

std::optional<uint32_t> RenderGraph::findPass(std::string_view name) const {
    for (uint32_t p = 0; p < mDecl.passes.size(); ++p)
        if (mDecl.passes[p].name == name) return p;
    return std::nullopt;
}

std::optional<uint32_t> RenderGraph::findResource(std::string_view name) const {
    for (uint32_t r = 0; r < mDecl.resources.size(); ++r)
        if (mDecl.resources[r].name == name) return r;
    return std::nullopt;
}

uint32_t RenderGraph::beginPass(std::string name, PassType type) {
    PassDecl pass;
    pass.name = std::move(name);
    pass.type = type;
    mDecl.passes.push_back(std::move(pass));
    mCallbacks.emplace_back();
    mPassData.emplace_back();
    return static_cast<uint32_t>(mDecl.passes.size() - 1);
}

uint32_t RenderGraph::addResource(ResourceDecl resource) {
    mDecl.resources.push_back(std::move(resource));
    return static_cast<uint32_t>(mDecl.resources.size() - 1);
}

AccessDecl& RenderGraph::addRead(uint32_t pass, ResourceKind kind, uint32_t index, uint32_t version, Usage usage,
                                 VkPipelineStageFlags2 stageOverride) {
    const std::string what = "pass " + quotedName(mDecl.passes[pass].name) + " reads";
    const ResourceDecl& resource = checkHandle(mDecl, what, kind, index, version);
    if (usageWrites(usage))
        throw GraphError(what + " " + quotedName(resource.name) + " with writing usage " + usageName(usage) +
                         " (use write())");
    checkTransferUsage(mDecl.passes[pass], what, resource, usage);
    AccessDecl access;
    access.resource = index;
    access.version = version;
    access.usage = usage;
    access.stageOverride = stageOverride;
    return mDecl.passes[pass].reads.emplace_back(access);
}

// `version` is the consumed handle's version; the access produces version + 1.
AccessDecl& RenderGraph::addWrite(uint32_t pass, ResourceKind kind, uint32_t index, uint32_t version, Usage usage,
                                  WriteMode mode, VkPipelineStageFlags2 stageOverride) {
    const std::string what = "pass " + quotedName(mDecl.passes[pass].name) + " writes";
    checkHandle(mDecl, what, kind, index, version);
    ResourceDecl& resource = mDecl.resources[index];
    if (!usageWrites(usage))
        throw GraphError(what + " " + quotedName(resource.name) + " with read-only usage " + usageName(usage) +
                         " (use read())");
    checkTransferUsage(mDecl.passes[pass], what, resource, usage);
    AccessDecl access;
    access.resource = index;
    access.version = version + 1;
    access.usage = usage;
    access.stageOverride = stageOverride;
    access.mode = mode;
    // Writing an older version is allowed here; validate reports the clash with its first producer.
    resource.versionCount = std::max(resource.versionCount, access.version + 1);
    return mDecl.passes[pass].writes.emplace_back(access);
}

}  // namespace candela::graph
