#include "vk/buffer.h"

#include "vk/check.h"
#include "vk/context.h"

#include <utility>

namespace candela::vk {

void Buffer::create(Context& context, const BufferDesc& desc) {
    mContext = &context;
    mSize = desc.size;
    mUsage = desc.usage;
    const VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                                  .size = desc.size,
                                  .usage = desc.usage,
                                  .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
    VK_CHECK(vkCreateBuffer(context.device(), &info, nullptr, &mBuffer));
    context.countCreated();
    context.setName(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(mBuffer), desc.name);
}

Buffer::Buffer(Context& context, const BufferDesc& desc) {
    create(context, desc);
    try {
        VkMemoryRequirements requirements;
        vkGetBufferMemoryRequirements(context.device(), mBuffer, &requirements);
        try {
            mAllocation = context.allocator().allocate(requirements, desc.memory, ResourceTiling::Linear);
        } catch (const OutOfDeviceMemory& e) {
            throw OutOfDeviceMemory("cannot allocate " + formatBytes(requirements.size) + " for buffer '" +
                                    (desc.name ? desc.name : "unnamed") + "': " + e.what());
        }
        VK_CHECK(vkBindBufferMemory(context.device(), mBuffer, mAllocation.memory, mAllocation.offset));
    } catch (...) {
        release();
        throw;
    }
}

Buffer::Buffer(Context& context, const BufferDesc& desc, const ExternalMemory& memory) {
    create(context, desc);
    try {
        VkMemoryRequirements requirements;
        vkGetBufferMemoryRequirements(context.device(), mBuffer, &requirements);
        checkFits(requirements, memory, desc.name);
        VK_CHECK(vkBindBufferMemory(context.device(), mBuffer, memory.memory, memory.offset));
    } catch (...) {
        release();
        throw;
    }
}

Buffer::~Buffer() { release(); }

Buffer::Buffer(Buffer&& other) noexcept
    : mContext(std::exchange(other.mContext, nullptr)),
      mBuffer(std::exchange(other.mBuffer, VK_NULL_HANDLE)),
      mAllocation(std::exchange(other.mAllocation, {})),
      mSize(std::exchange(other.mSize, 0)),
      mUsage(std::exchange(other.mUsage, 0)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        release();
        mContext = std::exchange(other.mContext, nullptr);
        mBuffer = std::exchange(other.mBuffer, VK_NULL_HANDLE);
        mAllocation = std::exchange(other.mAllocation, {});
        mSize = std::exchange(other.mSize, 0);
        mUsage = std::exchange(other.mUsage, 0);
    }
    return *this;
}

void Buffer::release() {
    if (!mBuffer) return;
    Context* context = mContext;
    context->defer([context, buffer = mBuffer, allocation = mAllocation] {
        vkDestroyBuffer(context->device(), buffer, nullptr);
        context->allocator().free(allocation);
        context->countDestroyed();
    });
    mBuffer = VK_NULL_HANDLE;
    mAllocation = {};
}

void Buffer::invalidate() const {
    if (!mAllocation.mapped || mAllocation.coherent) return;
    const VkMappedMemoryRange range{.sType = VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE,
                                    .memory = mAllocation.memory,
                                    .offset = 0,
                                    .size = VK_WHOLE_SIZE};
    VK_CHECK(vkInvalidateMappedMemoryRanges(mContext->device(), 1, &range));
}

void Buffer::flush() const {
    if (!mAllocation.mapped || mAllocation.coherent) return;
    const VkMappedMemoryRange range{.sType = VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE,
                                    .memory = mAllocation.memory,
                                    .offset = 0,
                                    .size = VK_WHOLE_SIZE};
    VK_CHECK(vkFlushMappedMemoryRanges(mContext->device(), 1, &range));
}

}  // namespace candela::vk
