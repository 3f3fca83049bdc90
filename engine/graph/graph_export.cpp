// Graphviz dot and JSON views of a compiled graph, for the graph panel, reports and debugging.

#include "graph/graph_export.h"

#include "graph/compile_steps.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <utility>

namespace candela::graph {

namespace {

using Json = nlohmann::ordered_json;

const char* layoutName(VkImageLayout layout) {
    switch (layout) {
    case VK_IMAGE_LAYOUT_UNDEFINED: return "UNDEFINED";
    case VK_IMAGE_LAYOUT_GENERAL: return "GENERAL";
    case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL: return "COLOR_ATTACHMENT_OPTIMAL";
    case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL: return "DEPTH_STENCIL_ATTACHMENT_OPTIMAL";
    case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL: return "DEPTH_STENCIL_READ_ONLY_OPTIMAL";
    case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL: return "SHADER_READ_ONLY_OPTIMAL";
    case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL: return "TRANSFER_SRC_OPTIMAL";
    case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL: return "TRANSFER_DST_OPTIMAL";
    case VK_IMAGE_LAYOUT_PREINITIALIZED: return "PREINITIALIZED";
    case VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL: return "DEPTH_ATTACHMENT_OPTIMAL";
    case VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL: return "DEPTH_READ_ONLY_OPTIMAL";
    case VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL: return "READ_ONLY_OPTIMAL";
    case VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL: return "ATTACHMENT_OPTIMAL";
    case VK_IMAGE_LAYOUT_PRESENT_SRC_KHR: return "PRESENT_SRC_KHR";
    default: return "OTHER";
    }
}

struct FlagName {
    VkFlags64 bit;
    const char* name;
};

constexpr FlagName kStageNames[] = {
    {VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, "TOP_OF_PIPE"},
    {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, "DRAW_INDIRECT"},
    {VK_PIPELINE_STAGE_2_VERTEX_INPUT_BIT, "VERTEX_INPUT"},
    {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, "VERTEX_SHADER"},
    {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, "FRAGMENT_SHADER"},
    {VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT, "EARLY_FRAGMENT_TESTS"},
    {VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, "LATE_FRAGMENT_TESTS"},
    {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, "COLOR_ATTACHMENT_OUTPUT"},
    {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, "COMPUTE_SHADER"},
    {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, "ALL_TRANSFER"},
    {VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, "BOTTOM_OF_PIPE"},
    {VK_PIPELINE_STAGE_2_HOST_BIT, "HOST"},
    {VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT, "ALL_GRAPHICS"},
    {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, "ALL_COMMANDS"},
    {VK_PIPELINE_STAGE_2_COPY_BIT, "COPY"},
    {VK_PIPELINE_STAGE_2_RESOLVE_BIT, "RESOLVE"},
    {VK_PIPELINE_STAGE_2_BLIT_BIT, "BLIT"},
    {VK_PIPELINE_STAGE_2_CLEAR_BIT, "CLEAR"},
    {VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT, "INDEX_INPUT"},
    {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, "VERTEX_ATTRIBUTE_INPUT"},
};

constexpr FlagName kAccessNames[] = {
    {VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT, "INDIRECT_COMMAND_READ"},
    {VK_ACCESS_2_INDEX_READ_BIT, "INDEX_READ"},
    {VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT, "VERTEX_ATTRIBUTE_READ"},
    {VK_ACCESS_2_UNIFORM_READ_BIT, "UNIFORM_READ"},
    {VK_ACCESS_2_SHADER_READ_BIT, "SHADER_READ"},
    {VK_ACCESS_2_SHADER_WRITE_BIT, "SHADER_WRITE"},
    {VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT, "COLOR_ATTACHMENT_READ"},
    {VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, "COLOR_ATTACHMENT_WRITE"},
    {VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT, "DEPTH_STENCIL_ATTACHMENT_READ"},
    {VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, "DEPTH_STENCIL_ATTACHMENT_WRITE"},
    {VK_ACCESS_2_TRANSFER_READ_BIT, "TRANSFER_READ"},
    {VK_ACCESS_2_TRANSFER_WRITE_BIT, "TRANSFER_WRITE"},
    {VK_ACCESS_2_HOST_READ_BIT, "HOST_READ"},
    {VK_ACCESS_2_HOST_WRITE_BIT, "HOST_WRITE"},
    {VK_ACCESS_2_MEMORY_READ_BIT, "MEMORY_READ"},
    {VK_ACCESS_2_MEMORY_WRITE_BIT, "MEMORY_WRITE"},
    {VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, "SHADER_SAMPLED_READ"},
    {VK_ACCESS_2_SHADER_STORAGE_READ_BIT, "SHADER_STORAGE_READ"},
    {VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, "SHADER_STORAGE_WRITE"},
};

// Names of the set bits; bits without a name appear as hex so nothing is silently dropped.
template <size_t N>
std::vector<std::string> flagNames(VkFlags64 flags, const FlagName (&names)[N]) {
    std::vector<std::string> result;
    for (const FlagName& entry : names) {
        if ((flags & entry.bit) == 0) continue;
        result.emplace_back(entry.name);
        flags &= ~entry.bit;
    }
    if (flags != 0) {
        char hex[32];
        std::snprintf(hex, sizeof(hex), "0x%llx", static_cast<unsigned long long>(flags));
        result.emplace_back(hex);
    }
    return result;
}

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

Json accessesJson(const GraphDecl& decl, const std::vector<AccessDecl>& accesses) {
    Json list = Json::array();
    for (const AccessDecl& access : accesses) {
        list.push_back({{"resource", decl.resources[access.resource].name},
                        {"version", access.version},
                        {"usage", usageName(access.usage)}});
    }
    return list;
}

Json barrierJson(const GraphDecl& decl, const Barrier& barrier, const std::string& before) {
    return {{"before", before},
            {"resource", decl.resources[barrier.resource].name},
            {"srcStages", flagNames(barrier.src.stages, kStageNames)},
            {"srcAccess", flagNames(barrier.src.access, kAccessNames)},
            {"dstStages", flagNames(barrier.dst.stages, kStageNames)},
            {"dstAccess", flagNames(barrier.dst.access, kAccessNames)},
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

std::string resourceLabel(const ResourceDecl& resource, const Lifetime& lifetime, const Placement& placement) {
    std::string label = dotEscape(resource.name) + "\\n";
    if (resource.kind == ResourceKind::Texture) {
        label += std::to_string(resource.texture.width) + "x" + std::to_string(resource.texture.height) +
                 " fmt " + std::to_string(resource.texture.format);
    } else {
        label += std::to_string(resource.buffer.size) + " bytes";
    }
    if (resource.imported) label += " (imported)";
    if (resource.exported) label += " (exported)";
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
        compiled.placements.size() != decl.resources.size())
        throw GraphError("graph export: the compiled graph does not match the declaration (compile first)");
}

}  // namespace

std::string exportDot(const GraphDecl& decl, const CompiledGraph& compiled, const GraphTimings* timings) {
    checkMatches(decl, compiled);
    const std::vector<uint32_t> positions = orderPositions(decl, compiled);
    std::string dot = "digraph render_graph {\n  rankdir=LR;\n  node [fontname=\"Helvetica\"];\n";

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
                std::snprintf(ms, sizeof(ms), " %.3f ms", timings->gpuMs[p]);
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
               resourceLabel(resource, compiled.lifetimes[r], compiled.placements[r]) + "\"];\n";
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
        entry["reads"] = accessesJson(decl, pass.reads);
        entry["writes"] = accessesJson(decl, pass.writes);
        passes.push_back(std::move(entry));
    }
    root["passes"] = std::move(passes);

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
             {"format", texture ? Json(static_cast<int>(resource.texture.format)) : Json(nullptr)},
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
