#include "render/frame.h"

#include <algorithm>

namespace candela {

graph::BufferId Frame::addHostUpload(std::string name, std::vector<std::byte> bytes) {
    const graph::BufferId buffer =
        graph->importBuffer(std::move(name), {.size = std::max<VkDeviceSize>(bytes.size(), 16)}, graph::ResourceState{});
    hostUploads.push_back({buffer, std::move(bytes)});
    return buffer;
}

bool Frame::computesMaps() const {
    const graph::CompiledGraph& compiled = graph->compiled();
    const auto runs = [&](uint32_t pass) {
        return pass < compiled.passes.size() && compiled.passes[pass].cullReason == graph::CullReason::None;
    };
    for (uint32_t pass = precomputeBegin; pass < precomputeEnd; ++pass)
        if (runs(pass)) return true;
    return runs(sheenLutPass);
}

}  // namespace candela
