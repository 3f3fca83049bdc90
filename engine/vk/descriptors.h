#pragma once
// Descriptor sets for one frame: DescriptorAllocator hands out sets from pools that are reset
// together once the frame has completed; DescriptorWriter fills a set by reflected binding name and
// refuses to produce a set with an unwritten binding (lavapipe crashes on those, and it is
// undefined behaviour everywhere).

#include "vk/handle.h"
#include "vk/pipeline.h"

#include <string_view>
#include <vector>

namespace candela::vk {

class DescriptorAllocator {
public:
    explicit DescriptorAllocator(Context& context) : mContext(&context) {}
    // Allocates a set; grows by another pool when the current one is full.
    VkDescriptorSet allocate(VkDescriptorSetLayout layout);
    // Recycles every set handed out. Precondition: the GPU no longer uses them.
    void reset();

private:
    void addPool();
    Context* mContext;
    std::vector<DescriptorPool> mPools;
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
