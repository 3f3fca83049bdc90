#pragma once
// Move-only RAII buffer with sub-allocated memory. Destruction is deferred through the context
// until the frames that may use it have completed.

#include "vk/memory.h"

#include <vulkan/vulkan_core.h>

#include <cstddef>
#include <span>

namespace candela::vk {

class Context;

struct BufferDesc {
    VkDeviceSize size = 0;
    VkBufferUsageFlags usage = 0;
    MemoryUsage memory = MemoryUsage::GpuOnly;
    const char* name = nullptr;  // debug name
};

class Buffer {
public:
    Buffer() = default;
    // Creates the buffer and binds memory. Precondition: desc.size > 0.
    Buffer(Context& context, const BufferDesc& desc);
    // Creates the buffer bound to memory owned by someone else (who must outlive its use).
    // desc.memory is ignored; mapped() is null.
    Buffer(Context& context, const BufferDesc& desc, const ExternalMemory& memory);
    ~Buffer();
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    VkBuffer handle() const { return mBuffer; }
    VkDeviceSize size() const { return mSize; }
    VkBufferUsageFlags usage() const { return mUsage; }
    explicit operator bool() const { return mBuffer != VK_NULL_HANDLE; }

    // Host-visible buffers only (Upload/Readback); null otherwise.
    std::byte* mapped() const { return mAllocation.mapped; }
    // Makes device writes visible to the host (non-coherent memory); call after the fence wait.
    void invalidate() const;
    // Makes host writes visible to the device (non-coherent memory).
    void flush() const;

private:
    void create(Context& context, const BufferDesc& desc);
    void release();
    Context* mContext = nullptr;
    VkBuffer mBuffer = VK_NULL_HANDLE;
    Allocation mAllocation;
    VkDeviceSize mSize = 0;
    VkBufferUsageFlags mUsage = 0;
};

}  // namespace candela::vk
