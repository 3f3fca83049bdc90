#pragma once
// Descriptor sets for one frame: DescriptorAllocator hands out sets from pools that are reset
// together once the frame has completed; DescriptorWriter fills a set by reflected binding name and
// refuses to produce a set with an unwritten binding (lavapipe crashes on those, and it is
// undefined behaviour everywhere).

#include "vk/handle.h"
#include "vk/pipeline.h"

#include <iterator>
#include <string_view>
#include <vector>

namespace candela::vk {

// The descriptors one or more sets take, by type (the pool sizes a set layout needs).
struct DescriptorCounts {
    // The descriptor types Candela's programs use; a pool holds only these.
    static constexpr VkDescriptorType kTypes[] = {
        VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, VK_DESCRIPTOR_TYPE_SAMPLER,
        VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,          VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
    static constexpr size_t kTypeCount = std::size(kTypes);

    uint32_t sets = 0;
    uint32_t descriptors[kTypeCount] = {};

    // The counts of one set of `program`'s layout `set`. Throws InternalError for a descriptor
    // type outside kTypes.
    static DescriptorCounts ofSet(const Program& program, uint32_t set);
    DescriptorCounts& operator+=(const DescriptorCounts& other);
    DescriptorCounts operator*(uint32_t times) const;
    // Whether `need` fits in what is left of these counts.
    bool holds(const DescriptorCounts& need) const;
};

// Hands out descriptor sets from pools. It tracks what each pool has left itself and moves to the
// next pool before a pool would overflow, so running out of a pool is the same on every device
// (lavapipe never checks pool capacity; AMD and Intel fail the allocation). There is no cap: a
// new pool is made when none has room, sized for the request, for what reserve() announced, or
// twice the previous pool, whichever is largest.
class DescriptorAllocator {
public:
    // `poolSets`: the sets of the first pool (its descriptors: kDefaultPerSet of each type per set).
    explicit DescriptorAllocator(Context& context, uint32_t poolSets = 64) : mContext(&context), mPoolSets(poolSets) {}
    // Allocates a set of `layout`, which takes `counts` (DescriptorCounts::ofSet, sets = 1).
    VkDescriptorSet allocate(VkDescriptorSetLayout layout, const DescriptorCounts& counts);
    // Announces that `total` will be allocated (e.g. one set per material of a scene): the next
    // pool made holds all of it, so a scene's sets take one pool.
    void reserve(const DescriptorCounts& total) { mReserved = total; }
    // Recycles every set handed out. Precondition: the GPU no longer uses them.
    void reset();
    // Pools made so far (tests).
    size_t poolCount() const { return mPools.size(); }

    // Descriptors of each type per set in a default pool.
    static constexpr uint32_t kDefaultPerSet = 4;

private:
    struct Pool {
        DescriptorPool pool;
        DescriptorCounts capacity;
        DescriptorCounts left;
    };
    void addPool(const DescriptorCounts& need);
    Context* mContext;
    uint32_t mPoolSets;
    DescriptorCounts mReserved;
    std::vector<Pool> mPools;
    size_t mCurrent = 0;
};

class DescriptorWriter {
public:
    // Writes set `set` of `program`'s layout.
    DescriptorWriter(const Program& program, uint32_t set) : mProgram(&program), mSet(set) {}

    // Binds by the GLSL variable name. Throws InternalError naming the program if the set has no
    // such binding or its type does not match.
    DescriptorWriter& image(std::string_view name, VkImageView view, VkImageLayout layout,
                            VkSampler sampler = VK_NULL_HANDLE);
    DescriptorWriter& buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset = 0,
                             VkDeviceSize range = VK_WHOLE_SIZE);

    // Allocates the set and writes it. Throws InternalError naming the first binding the layout
    // declares that was not written.
    VkDescriptorSet commit(Context& context, DescriptorAllocator& allocator) const;

private:
    const shader::DescriptorBinding& find(std::string_view name, bool imageKind) const;
    struct Pending {
        uint32_t binding;
        VkDescriptorType type;
        VkDescriptorImageInfo image;
        VkDescriptorBufferInfo buffer;
    };
    const Program* mProgram;
    uint32_t mSet;
    std::vector<Pending> mWrites;
};

}  // namespace candela::vk
