// The device layer on a real Vulkan device: sub-allocation, staging uploads, deferred destruction,
// descriptor completeness, and VK_CHECK's error text.
#include "gpu_test.h"

#include "vk/buffer.h"
#include "vk/check.h"
#include "vk/commands.h"
#include "vk/descriptors.h"
#include "vk/image.h"
#include "vk/library_pin.h"
#include "vk/pipeline.h"
#include "vk/upload.h"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <numeric>
#include <vector>

namespace candela::test {
namespace {

TEST_F(GpuTest, SmallBuffersShareDeviceMemoryBlocks) {
    const uint32_t before = context().allocator().stats().deviceMemoryObjects;
    std::vector<vk::Buffer> buffers;
    for (int i = 0; i < 200; ++i)
        buffers.emplace_back(context(), vk::BufferDesc{.size = 4096 + 16u * i, .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT});
    // 200 buffers of ~4-8 KiB fit in one 64 MiB block.
    EXPECT_LE(context().allocator().stats().deviceMemoryObjects - before, 1u);
    EXPECT_EQ(context().allocator().stats().liveAllocations, 200u);
    buffers.clear();
    context().waitIdleAndCollect();
    EXPECT_EQ(context().allocator().stats().liveAllocations, 0u);
    EXPECT_EQ(context().liveObjects(), 0);
}

TEST_F(GpuTest, DeferredDestructionWaitsForTheFrame) {
    {
        vk::Buffer buffer(context(), {.size = 256, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT});
        EXPECT_EQ(context().liveObjects(), 1);
    }
    // Dropped but not yet destroyed: the current frame has not completed.
    EXPECT_EQ(context().liveObjects(), 1);
    context().waitIdleAndCollect();
    EXPECT_EQ(context().liveObjects(), 0);
}

// Also through 256 bytes of staging: the buffer goes in 128-byte pieces and the image (52-byte
// rows) two rows at a time, over many submits, and reads back the same.
TEST_F(GpuTest, UploadedBufferAndImageReadBackIdentical) {
  for (const VkDeviceSize chunk : {VkDeviceSize(0), VkDeviceSize(256)}) {
    SCOPED_TRACE("staging chunk " + std::to_string(chunk));
    std::vector<uint32_t> words(1000);
    std::iota(words.begin(), words.end(), 7u);
    vk::Buffer device(context(), {.size = words.size() * 4,
                                  .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT});
    const uint32_t w = 13, h = 7;
    std::vector<uint8_t> texels(w * h * 4);
    for (size_t i = 0; i < texels.size(); ++i) texels[i] = static_cast<uint8_t>(i * 31 + 5);
    vk::Image image(context(), {.width = w, .height = h, .format = VK_FORMAT_R8G8B8A8_UNORM,
                                .usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
    vk::Uploader uploader(context(), chunk);
    uploader.buffer(device, std::as_bytes(std::span(words)));
    uploader.image(image, std::as_bytes(std::span(texels)), 0, 0, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    uploader.submitAndWait();
    if (chunk) {
        EXPECT_EQ(uploader.chunkBytes(), chunk);
        EXPECT_GT(uploader.submits(), 10u);
    } else {
        EXPECT_EQ(uploader.submits(), 1u);
    }

    vk::Buffer readback(context(), {.size = words.size() * 4 + texels.size(),
                                    .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    .memory = vk::MemoryUsage::Readback});
    vk::OneShotCommands commands(context());
    VkCommandBuffer cmd = commands.begin();
    const VkBufferCopy copy{0, 0, words.size() * 4};
    vkCmdCopyBuffer(cmd, device.handle(), readback.handle(), 1, &copy);
    const VkBufferImageCopy region{.bufferOffset = words.size() * 4,
                                   .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                   .imageExtent = {w, h, 1}};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 1, &region);
    copiesToHostBarrier(cmd);
    commands.submitAndWait();
    readback.invalidate();
    EXPECT_EQ(std::memcmp(readback.mapped(), words.data(), words.size() * 4), 0);
    EXPECT_EQ(std::memcmp(readback.mapped() + words.size() * 4, texels.data(), texels.size()), 0);
  }
}

TEST_F(GpuTest, DescriptorWriterRefusesUnwrittenBindingsAndUnknownNames) {
    const vk::Pipeline pipeline = vk::Pipeline::compute(context(), "pattern.comp");
    vk::DescriptorAllocator allocator(context());
    try {
        vk::DescriptorWriter(pipeline.program(), 0).commit(context(), allocator);
        FAIL() << "expected a throw";
    } catch (const InternalError& e) {
        EXPECT_NE(std::string(e.what()).find("'outImage'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(vk::DescriptorWriter(pipeline.program(), 0).image("noSuchImage", VK_NULL_HANDLE, VK_IMAGE_LAYOUT_GENERAL),
                 InternalError);
}

TEST_F(GpuTest, ProgramLayoutComesFromReflection) {
    const vk::Pipeline pipeline = vk::Pipeline::compute(context(), "pattern.comp");
    ASSERT_EQ(pipeline.program().setCount(), 1u);
    EXPECT_EQ(pipeline.program().reflection().pushConstants.size, 16u);
}

TEST(VkCheck, ErrorNamesCallFileLineAndResult) {
    try {
        VK_CHECK(VK_ERROR_OUT_OF_DEVICE_MEMORY);
        FAIL() << "expected a throw";
    } catch (const vk::VulkanError& e) {
        const std::string text = e.what();
        EXPECT_NE(text.find("VK_ERROR_OUT_OF_DEVICE_MEMORY failed at"), std::string::npos) << text;
        EXPECT_NE(text.find("device_layer_test.cpp:"), std::string::npos) << text;
        EXPECT_NE(text.find(": VK_ERROR_OUT_OF_DEVICE_MEMORY"), std::string::npos) << text;
        EXPECT_EQ(e.result(), VK_ERROR_OUT_OF_DEVICE_MEMORY);
    }
}

// vk/library_pin.h: contexts created and destroyed one after another in one process (a test binary,
// a program that embeds Candela) load the driver and layers once and keep them. Unpinned, the
// loader unloads and reloads them for every context, and NVIDIA's driver fails to load again after
// about 30 cycles (its static TLS is not given back). 40 contexts, each under validation; every
// library loaded while the first lived is loaded still after the last.
TEST(ContextLifetime, ContextsComeAndGoWithTheDriverLoadedOnce) {
    std::vector<std::string> during;
    for (int i = 0; i < 40; ++i) {
        vk::Context context(vk::ContextDesc{.validation = true});
        ASSERT_TRUE(context.validationEnabled());
        if (i == 0) during = vk::loadedLibraries();
        for (const vk::ValidationMessage& m : context.validationMessages())
            if (!bestPracticesNotApplicable(m.text)) ADD_FAILURE() << "validation: " << m.text;
    }
    const std::vector<std::string> after = vk::loadedLibraries();
    std::vector<std::string> unloaded;
    std::set_difference(during.begin(), during.end(), after.begin(), after.end(), std::back_inserter(unloaded));
    EXPECT_TRUE(unloaded.empty()) << unloaded.size() << " libraries unloaded, the first " << unloaded.front();
}

}  // namespace
}  // namespace candela::test
