#include "vk/descriptors.h"

#include "vk/check.h"

#include <algorithm>


namespace candela::vk {

DescriptorCounts DescriptorCounts::ofSet(const Program& program, uint32_t set) {
    DescriptorCounts counts;
    counts.sets = 1;
    for (const shader::DescriptorBinding& b : program.reflection().bindings) {
        if (b.set != set) continue;
        const auto* type = std::find(std::begin(kTypes), std::end(kTypes), b.type);
        if (type == std::end(kTypes))
            throw InternalError(program.name() + ": binding '" + b.name + "' has a descriptor type the pools do not hold");
        counts.descriptors[type - std::begin(kTypes)] += b.count;
    }
    return counts;
}

DescriptorCounts& DescriptorCounts::operator+=(const DescriptorCounts& other) {
    sets += other.sets;
    for (size_t i = 0; i < kTypeCount; ++i) descriptors[i] += other.descriptors[i];
    return *this;
}

DescriptorCounts DescriptorCounts::operator*(uint32_t times) const {
    DescriptorCounts out;
    out.sets = sets * times;
    for (size_t i = 0; i < kTypeCount; ++i) out.descriptors[i] = descriptors[i] * times;
    return out;
}

bool DescriptorCounts::holds(const DescriptorCounts& need) const {
    if (need.sets > sets) return false;
    for (size_t i = 0; i < kTypeCount; ++i)
        if (need.descriptors[i] > descriptors[i]) return false;
    return true;
}

void DescriptorAllocator::addPool(const DescriptorCounts& need) {
    // The largest of: the default pool, twice the last pool, what reserve() announced, the request.
    DescriptorCounts size;
    size.sets = mPoolSets;
    for (uint32_t& d : size.descriptors) d = mPoolSets * kDefaultPerSet;
    if (!mPools.empty()) size = mPools.back().capacity * 2;
    for (const DescriptorCounts* other : {static_cast<const DescriptorCounts*>(&mReserved), &need}) {
        size.sets = std::max(size.sets, other->sets);
        for (size_t i = 0; i < DescriptorCounts::kTypeCount; ++i)
            size.descriptors[i] = std::max(size.descriptors[i], other->descriptors[i]);
    }
    mReserved = {};
    std::vector<VkDescriptorPoolSize> sizes;
    for (size_t i = 0; i < DescriptorCounts::kTypeCount; ++i)
        if (size.descriptors[i] > 0) sizes.push_back({DescriptorCounts::kTypes[i], size.descriptors[i]});
    const VkDescriptorPoolCreateInfo info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                          .maxSets = size.sets,
                                          .poolSizeCount = static_cast<uint32_t>(sizes.size()),
                                          .pPoolSizes = sizes.data()};
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorPool(mContext->device(), &info, nullptr, &pool));
    mPools.push_back({DescriptorPool(*mContext, pool), size, size});
}

VkDescriptorSet DescriptorAllocator::allocate(VkDescriptorSetLayout layout, const DescriptorCounts& counts) {
    // Past pools that cannot hold the set: each pool is tried once per reset, so a full pool is
    // left behind for good.
    while (mCurrent < mPools.size() && !mPools[mCurrent].left.holds(counts)) ++mCurrent;
    for (bool fresh = false;; fresh = true) {
        if (mCurrent == mPools.size()) addPool(counts);
        Pool& pool = mPools[mCurrent];
        const VkDescriptorSetAllocateInfo info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                               .descriptorPool = pool.pool.get(),
                                               .descriptorSetCount = 1,
                                               .pSetLayouts = &layout};
        VkDescriptorSet set = VK_NULL_HANDLE;
        const VkResult result = vkAllocateDescriptorSets(mContext->device(), &info, &set);
        if (result == VK_SUCCESS) {
            pool.left.sets -= counts.sets;
            for (size_t i = 0; i < DescriptorCounts::kTypeCount; ++i) pool.left.descriptors[i] -= counts.descriptors[i];
            return set;
        }
        // The driver may still refuse (fragmentation): move to a new pool, once.
        if (result != VK_ERROR_OUT_OF_POOL_MEMORY && result != VK_ERROR_FRAGMENTED_POOL) VK_CHECK(result);
        if (fresh) VK_CHECK(result);
        mCurrent = mPools.size();
    }
}

void DescriptorAllocator::reset() {
    for (Pool& pool : mPools) {
        VK_CHECK(vkResetDescriptorPool(mContext->device(), pool.pool.get(), 0));
        pool.left = pool.capacity;
    }
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
    const VkDescriptorSet set = allocator.allocate(mProgram->setLayout(mSet), DescriptorCounts::ofSet(*mProgram, mSet));
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
