// Graphviz dot and JSON views of a compiled graph, for the graph panel, reports and debugging.

#include "graph/graph_export.h"

#include "graph/compile_steps.h"

#include <nlohmann/json.hpp>
#include <vulkan/vulkan.hpp>

#include <cstdio>
#include <utility>

namespace candela::graph {

namespace {

using Json = nlohmann::ordered_json;

// Enum and flag names come from Vulkan-Hpp's to_string ("ColorAttachmentOptimal",
// "R16G16B16A16Sfloat"); flag sets become lists of names.
std::string layoutName(VkImageLayout layout) { return vk::to_string(static_cast<vk::ImageLayout>(layout)); }
std::string formatName(VkFormat format) { return vk::to_string(static_cast<vk::Format>(format)); }

template <class Flags>
Json flagNames(Flags flags) {
    std::string text = vk::to_string(flags);  // "{ A | B }", or "{}" when empty
    Json names = Json::array();
    if (text.size() <= 4) return names;
    text = text.substr(2, text.size() - 4);
    for (size_t start = 0;;) {
        const size_t bar = text.find(" | ", start);
        names.push_back(text.substr(start, bar - start));
        if (bar == std::string::npos) break;
        start = bar + 3;
    }
    return names;
}
Json stageNames(VkPipelineStageFlags2 stages) { return flagNames(vk::PipelineStageFlags2(stages)); }
Json accessNames(VkAccessFlags2 access) { return flagNames(vk::AccessFlags2(access)); }

Json optionalIndex(uint32_t value) { return value == kInvalidIndex ? Json(nullptr) : Json(value); }

// Position of each pass in compiled.order (kInvalidIndex if culled).
std::vector<uint32_t> orderPositions(const GraphDecl& decl, const CompiledGraph& compiled) {
    std::vector<uint32_t> positions(decl.passes.size(), kInvalidIndex);
    for (uint32_t i = 0; i < compiled.order.size(); ++i) positions[compiled.order[i]] = i;
    return positions;
}

bool timed(const GraphTimings* timings, uint32_t pass) {
    return timings != nullptr && pass < timings->gpuMs.size() && timings->gpuMs[pass] >= 0.0;
}

// `info`: the pass's PassInfo; `writes`: the list is its writes, whose unreadWrites give "read".
// Attachments of a running pass carry their planned load and store operations.
Json accessesJson(const GraphDecl& decl, const std::vector<AccessDecl>& accesses, const PassInfo& info, bool writes) {
    Json list = Json::array();
    for (const AccessDecl& access : accesses) {
        Json entry = {{"resource", decl.resources[access.resource].name},
                      {"version", access.version},
                      {"usage", usageName(access.usage)}};
        if (access.usage == Usage::ResolveAttachment) entry["resolveFrom"] = decl.resources[access.resolveSource].name;
        if (writes) entry["read"] = !info.writeUnread(access.resource);
        if (const AttachmentOps* ops = info.attachmentOps(access.resource);
            ops && (access.usage == Usage::ColorAttachment || access.usage == Usage::DepthAttachment ||
                    access.usage == Usage::DepthRead)) {
            entry["loadOp"] = loadOpName(ops->load);
            entry["storeOp"] = storeOpName(ops->store);
        }
        list.push_back(std::move(entry));
    }
    return list;
}

Json barrierJson(const GraphDecl& decl, const Barrier& barrier, const std::string& before) {
    return {{"before", before},
            {"resource", decl.resources[barrier.resource].name},
            {"srcStages", stageNames(barrier.src.stages)},
            {"srcAccess", accessNames(barrier.src.access)},
            {"dstStages", stageNames(barrier.dst.stages)},
            {"dstAccess", accessNames(barrier.dst.access)},
            {"oldLayout", layoutName(barrier.src.layout)},
            {"newLayout", layoutName(barrier.dst.layout)},
            {"aliasedFrom", barrier.aliasedFrom == kInvalidIndex
                                ? Json(nullptr)
                                : Json(decl.resources[barrier.aliasedFrom].name)}};
}

// Dot strings are quoted; escape what would end them.
std::string dotEscape(const std::string& text) {
    std::string escaped;
    for (char c : text) {
        if (c == '"' || c == '\\') escaped += '\\';
        escaped += c;
    }
    return escaped;
}

std::string resourceLabel(const ResourceDecl& resource, const Lifetime& lifetime, const Placement& placement,
                          bool transientAttachment) {
    std::string label = dotEscape(resource.name) + "\\n";
    if (resource.kind == ResourceKind::Texture) {
        label += std::to_string(resource.texture.width) + "x" + std::to_string(resource.texture.height) +
                 " " + formatName(resource.texture.format);
        if (resource.texture.samples > 1) label += " x" + std::to_string(resource.texture.samples) + " samples";
    } else {
        label += std::to_string(resource.buffer.size) + " bytes";
    }
    if (resource.imported) label += " (imported)";
    if (resource.exported) label += " (exported)";
    if (transientAttachment) label += " (transient attachment)";
    label += lifetime.used()
                 ? "\\nlife " + std::to_string(lifetime.first) + ".." + std::to_string(lifetime.last)
                 : std::string("\\nunused");
    if (placement.heap != kInvalidIndex) {
        label += "\\nheap " + std::to_string(placement.heap) + " @ " + std::to_string(placement.offset) +
                 " (" + std::to_string(placement.size) + " B)";
    }
    return label;
}

// Both exports index compiled data by declared pass and resource.
void checkMatches(const GraphDecl& decl, const CompiledGraph& compiled) {
    if (compiled.passes.size() != decl.passes.size() || compiled.lifetimes.size() != decl.resources.size() ||
        compiled.placements.size() != decl.resources.size() ||
        compiled.transientAttachments.size() != decl.resources.size())
        throw GraphError("graph export: the compiled graph does not match the declaration (compile first)");
}

}  // namespace

std::string exportDot(const GraphDecl& decl, const CompiledGraph& compiled, const GraphTimings* timings) {
    checkMatches(decl, compiled);
    const std::vector<uint32_t> positions = orderPositions(decl, compiled);
    std::string dot = "digraph render_graph {\n  rankdir=LR;\n  node [fontname=\"Helvetica\"];\n";
    if (timings && timings->gpuMsUnreliable)
        dot += "  labelloc=b;\n  label=\"" + dotEscape(std::string("* ") + kUnreliableGpuTimes) + "\";\n";

    // Running passes first, in execution order; then the culled ones with their reasons.
    std::vector<uint32_t> passes = compiled.order;
    for (uint32_t p = 0; p < decl.passes.size(); ++p)
        if (positions[p] == kInvalidIndex) passes.push_back(p);
    for (uint32_t p : passes) {
        std::string label = dotEscape(decl.passes[p].name);
        std::string style = "shape=box, style=filled, fillcolor=\"#dde8f5\"";
        if (positions[p] != kInvalidIndex) {
            label += "\\n#" + std::to_string(positions[p]);
            if (timed(timings, p)) {
                char ms[32];
                std::snprintf(ms, sizeof(ms), " %.3f ms%s", timings->gpuMs[p], timings->gpuMsUnreliable ? "*" : "");
                label += ms;
            }
        } else {
            const PassInfo& info = compiled.passes[p];
            label += "\\nculled: " + std::string(cullReasonName(info.cullReason)) + "\\n" +
                     dotEscape(info.cullDetail);
            style = "shape=box, style=dashed, color=grey, fontcolor=grey";
        }
        dot += "  p" + std::to_string(p) + " [" + style + ", label=\"" + label + "\"];\n";
    }
    for (uint32_t r = 0; r < decl.resources.size(); ++r) {
        const ResourceDecl& resource = decl.resources[r];
        const std::string style = compiled.lifetimes[r].used() ? "shape=ellipse"
                                                               : "shape=ellipse, color=grey, fontcolor=grey";
        dot += "  r" + std::to_string(r) + " [" + style + ", label=\"" +
               resourceLabel(resource, compiled.lifetimes[r], compiled.placements[r], compiled.transientAttachments[r]) +
               "\"];\n";
    }
    for (uint32_t p : passes) {
        const std::string pass = std::string("p") + std::to_string(p);
        const std::string culled = positions[p] == kInvalidIndex ? ", style=dashed, color=grey" : "";
        for (const AccessDecl& access : decl.passes[p].reads) {
            dot += "  r" + std::to_string(access.resource) + " -> " + pass + " [label=\"v" +
                   std::to_string(access.version) + " " + usageName(access.usage) + "\"" + culled + "];\n";
        }
        for (const AccessDecl& access : decl.passes[p].writes) {
            dot += "  " + pass + " -> r" + std::to_string(access.resource) + " [label=\"v" +
                   std::to_string(access.version) + " " + usageName(access.usage) + "\"" + culled + "];\n";
        }
    }
    return dot + "}\n";
}

std::string exportJson(const GraphDecl& decl, const CompiledGraph& compiled, const GraphTimings* timings) {
    checkMatches(decl, compiled);
    const std::vector<uint32_t> positions = orderPositions(decl, compiled);
    Json root;

    Json passes = Json::array();
    for (uint32_t p = 0; p < decl.passes.size(); ++p) {
        const PassDecl& pass = decl.passes[p];
        const PassInfo& info = compiled.passes[p];
        const char* type = pass.type == PassType::Graphics  ? "graphics"
                           : pass.type == PassType::Compute ? "compute"
                                                            : "transfer";
        Json entry = {{"name", pass.name},
                      {"type", type},
                      {"order", optionalIndex(positions[p])},
                      {"culled", positions[p] == kInvalidIndex},
                      {"reason", cullReasonName(info.cullReason)},
                      {"detail", info.cullDetail}};
        if (timed(timings, p)) entry["gpuMs"] = timings->gpuMs[p];
        entry["reads"] = accessesJson(decl, pass.reads, info, false);
        entry["writes"] = accessesJson(decl, pass.writes, info, true);
        passes.push_back(std::move(entry));
    }
    root["passes"] = std::move(passes);
    if (timings && timings->gpuMsUnreliable) root["gpuMsUnreliable"] = kUnreliableGpuTimes;

    Json order = Json::array();
    for (uint32_t p : compiled.order) order.push_back(decl.passes[p].name);
    root["order"] = std::move(order);

    Json resources = Json::array();
    for (uint32_t r = 0; r < decl.resources.size(); ++r) {
        const ResourceDecl& resource = decl.resources[r];
        const bool texture = resource.kind == ResourceKind::Texture;
        const Placement& placement = compiled.placements[r];
        const bool placed = placement.heap != kInvalidIndex;
        resources.push_back(
            {{"name", resource.name},
             {"kind", texture ? "texture" : "buffer"},
             {"imported", resource.imported},
             {"exported", resource.exported},
             {"width", texture ? Json(resource.texture.width) : Json(nullptr)},
             {"height", texture ? Json(resource.texture.height) : Json(nullptr)},
             {"format", texture ? Json(formatName(resource.texture.format)) : Json(nullptr)},
             {"samples", texture ? Json(resource.texture.samples) : Json(nullptr)},
             {"transientAttachment", bool(compiled.transientAttachments[r])},
             {"size", placed ? placement.size : estimateMemoryRequirement(resource).size},
             {"first", optionalIndex(compiled.lifetimes[r].first)},
             {"last", optionalIndex(compiled.lifetimes[r].last)},
             {"heap", optionalIndex(placement.heap)},
             {"offset", placed ? Json(placement.offset) : Json(nullptr)}});
    }
    root["resources"] = std::move(resources);

    Json heaps = Json::array();
    for (const Heap& heap : compiled.heaps) {
        Json residents = Json::array();
        for (uint32_t r : heap.residents) residents.push_back(decl.resources[r].name);
        heaps.push_back({{"kind", heap.kind == ResourceKind::Texture ? "texture" : "buffer"},
                         {"size", heap.size},
                         {"alignment", heap.alignment},
                         {"memoryTypeBits", heap.memoryTypeBits},
                         {"residents", std::move(residents)}});
    }
    root["heaps"] = std::move(heaps);
    root["bytesRequested"] = compiled.bytesRequested;
    root["bytesAllocated"] = compiled.bytesAllocated;

    Json barriers = Json::array();
    for (size_t i = 0; i < compiled.barriers.size(); ++i)
        for (const Barrier& barrier : compiled.barriers[i])
            barriers.push_back(barrierJson(decl, barrier, decl.passes[compiled.order[i]].name));
    for (const Barrier& barrier : compiled.finalBarriers) barriers.push_back(barrierJson(decl, barrier, "end"));
    root["barriers"] = std::move(barriers);
    root["steps"] = compiled.steps;
    return root.dump(2);
}

}  // namespace candela::graph
