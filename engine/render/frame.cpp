#include "render/frame.h"

#include <algorithm>

namespace candela {

graph::BufferId Frame::addHostUpload(std::string name, std::vector<std::byte> bytes) {
    const graph::BufferId buffer =
        graph->importBuffer(std::move(name), {.size = std::max<VkDeviceSize>(bytes.size(), 16)}, graph::ResourceState{});
    hostUploads.push_back({buffer, std::move(bytes)});
    return buffer;
}

}  // namespace candela
