#include "vk/descriptors.h"

#include "vk/check.h"

#include <algorithm>


namespace candela::vk {

void DescriptorAllocator::addPool() {
    const VkDescriptorPoolSize sizes[] = {
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 256}, {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 256},
        {VK_DESCRIPTOR_TYPE_SAMPLER, 64},                 {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 128},
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 128},         {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 128},
    };
    const VkDescriptorPoolCreateInfo info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                          .maxSets = 256,
                                          .poolSizeCount = static_cast<uint32_t>(std::size(sizes)),
                                          .pPoolSizes = sizes};
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorPool(mContext->device(), &info, nullptr, &pool));
    mPools.emplace_back(*mContext, pool);
}

VkDescriptorSet DescriptorAllocator::allocate(VkDescriptorSetLayout layout) {
    for (;;) {
        if (mCurrent == mPools.size()) addPool();
        const VkDescriptorSetAllocateInfo info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                               .descriptorPool = mPools[mCurrent].get(),
                                               .descriptorSetCount = 1,
                                               .pSetLayouts = &layout};
        VkDescriptorSet set = VK_NULL_HANDLE;
        const VkResult result = vkAllocateDescriptorSets(mContext->device(), &info, &set);
        if (result == VK_SUCCESS) return set;
        // A full pool is not an error: move on to the next one (created on demand).
        if (result != VK_ERROR_OUT_OF_POOL_MEMORY && result != VK_ERROR_FRAGMENTED_POOL) VK_CHECK(result);
        if (++mCurrent > 64) throw InternalError("descriptor set layout does not fit an empty pool");
    }
}

void DescriptorAllocator::reset() {
    for (DescriptorPool& pool : mPools) VK_CHECK(vkResetDescriptorPool(mContext->device(), pool.get(), 0));
    mCurrent = 0;
}

const shader::DescriptorBinding& DescriptorWriter::find(std::string_view name, bool imageKind) const {
    for (const shader::DescriptorBinding& b : mProgram->reflection().bindings) {
        if (b.set != mSet || b.name != name) continue;
        const bool isImage = b.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER || b.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE ||
                             b.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE || b.type == VK_DESCRIPTOR_TYPE_SAMPLER;
        if (isImage != imageKind)
            throw InternalError(mProgram->name() + ": binding '" + std::string(name) + "' is not " +
                                   (imageKind ? "an image" : "a buffer"));
        return b;
    }
    throw InternalError(mProgram->name() + ": no binding named '" + std::string(name) + "' in set " +
                           std::to_string(mSet));
}

DescriptorWriter& DescriptorWriter::image(std::string_view name, VkImageView view, VkImageLayout layout, VkSampler sampler) {
    const shader::DescriptorBinding& b = find(name, true);
    if (b.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER && !sampler)
        throw InternalError(mProgram->name() + ": binding '" + std::string(name) + "' needs a sampler");
    mWrites.push_back({b.binding, b.type, {sampler, view, layout}, {}});
    return *this;
}

DescriptorWriter& DescriptorWriter::buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
    const shader::DescriptorBinding& b = find(name, false);
    mWrites.push_back({b.binding, b.type, {}, {buffer, offset, range}});
    return *this;
}

VkDescriptorSet DescriptorWriter::commit(Context& context, DescriptorAllocator& allocator) const {
    for (const shader::DescriptorBinding& b : mProgram->reflection().bindings) {
        if (b.set != mSet) continue;
        const bool written = std::any_of(mWrites.begin(), mWrites.end(), [&](const Pending& p) { return p.binding == b.binding; });
        if (!written)
            throw InternalError(mProgram->name() + ": binding '" + b.name + "' (set " + std::to_string(mSet) +
                                   ", binding " + std::to_string(b.binding) + ") was not written");
    }
    const VkDescriptorSet set = allocator.allocate(mProgram->setLayout(mSet));
    std::vector<VkWriteDescriptorSet> writes;
    writes.reserve(mWrites.size());
    for (const Pending& p : mWrites) {
        const bool isBuffer = p.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || p.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes.push_back({.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                          .dstSet = set,
                          .dstBinding = p.binding,
                          .descriptorCount = 1,
                          .descriptorType = p.type,
                          .pImageInfo = isBuffer ? nullptr : &p.image,
                          .pBufferInfo = isBuffer ? &p.buffer : nullptr});
    }
    vkUpdateDescriptorSets(context.device(), static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
    return set;
}

}  // namespace candela::vk
