#include "ui/imgui_pass.h"

#include "core/log.h"
#include "executor/graph_executor.h"
#include "vk/check.h"
#include "vk/commands.h"
#include "vk/context.h"

#include <imgui.h>
#include <backends/imgui_impl_vulkan.h>

#include <string>

namespace candela::ui {

using namespace graph;

namespace {

using Framebuffer = vk::Handle<VkFramebuffer, vkDestroyFramebuffer>;

// The backend reports failures through this callback (it cannot throw through C code).
void checkBackendResult(VkResult result) {
    if (result != VK_SUCCESS) log::error("ImGui Vulkan backend: " + std::string(vk::vkResultName(result)));
}

VkRenderPass createRenderPass(vk::Context& context, VkFormat format) {
    const VkAttachmentDescription color{.format = format,
                                        .samples = VK_SAMPLE_COUNT_1_BIT,
                                        .loadOp = VK_ATTACHMENT_LOAD_OP_LOAD,
                                        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                        .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                        .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                        .initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                        .finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    const VkSubpassDescription subpass{.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS,
                                       .colorAttachmentCount = 1,
                                       .pColorAttachments = &reference};
    const VkRenderPassCreateInfo info{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO,
                                      .attachmentCount = 1,
                                      .pAttachments = &color,
                                      .subpassCount = 1,
                                      .pSubpasses = &subpass};
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VK_CHECK(vkCreateRenderPass(context.device(), &info, nullptr, &renderPass));
    return renderPass;
}

}  // namespace

ImGuiPass::ImGuiPass(vk::Context& context, VkFormat format, uint32_t minImageCount, uint32_t imageCount)
    : mContext(context), mFormat(format) {
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    const VkDescriptorPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                              .flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT,
                                              .maxSets = 4,
                                              .poolSizeCount = 1,
                                              .pPoolSizes = &size};
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorPool(context.device(), &poolInfo, nullptr, &pool));
    mDescriptorPool = vk::DescriptorPool(context, pool);
    mRenderPass = createRenderPass(context, format);

    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context.instance();
    info.PhysicalDevice = context.physicalDevice();
    info.Device = context.device();
    info.QueueFamily = context.graphicsQueue().family;
    info.Queue = context.graphicsQueue().queue;
    info.DescriptorPool = mDescriptorPool.get();
    info.MinImageCount = std::max(2u, minImageCount);
    info.ImageCount = std::max(info.MinImageCount, imageCount);
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkBackendResult;
    if (!ImGui_ImplVulkan_Init(&info, mRenderPass)) {
        vkDestroyRenderPass(context.device(), mRenderPass, nullptr);
        throw vk::VulkanError("cannot start Dear ImGui's Vulkan backend", VK_ERROR_INITIALIZATION_FAILED);
    }
    vk::OneShotCommands upload(context);
    ImGui_ImplVulkan_CreateFontsTexture(upload.begin());
    upload.submitAndWait();
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

ImGuiPass::~ImGuiPass() {
    // The backend destroys its objects at once: no frame may still use them.
    mContext.waitIdleAndCollect();
    ImGui_ImplVulkan_Shutdown();
    vkDestroyRenderPass(mContext.device(), mRenderPass, nullptr);
}

TextureId ImGuiPass::add(RenderGraph& graph, TextureId target) {
    struct Data {
        TextureId target;
    };
    VkDevice device = mContext.device();
    VkRenderPass renderPass = mRenderPass;
    const Data& data = graph.addPass<Data>(
        "imgui", PassType::Graphics,
        // Drawn over the frame; kept (on black) when the passes before it are switched off.
        [&](PassBuilder& builder, Data& d) { d.target = builder.drawOver(target, VkClearColorValue{{0.0f, 0.0f, 0.0f, 1.0f}}); },
        [device, renderPass](const Data& d, PassContext& ctx) {
            ImDrawData* drawData = ImGui::GetDrawData();
            if (!drawData) return;
            const VkExtent2D extent = ctx.extent(d.target);
            const VkImageView view = ctx.view(d.target);
            const VkFramebufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO,
                                               .renderPass = renderPass,
                                               .attachmentCount = 1,
                                               .pAttachments = &view,
                                               .width = extent.width,
                                               .height = extent.height,
                                               .layers = 1};
            VkFramebuffer handle = VK_NULL_HANDLE;
            VK_CHECK(vkCreateFramebuffer(device, &info, nullptr, &handle));
            // Dropped at once: destruction waits (deferred) until this frame has completed.
            Framebuffer framebuffer(ctx.context(), handle);
            const VkRenderPassBeginInfo begin{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
                                              .renderPass = renderPass,
                                              .framebuffer = handle,
                                              .renderArea = {{0, 0}, extent}};
            vkCmdBeginRenderPass(ctx.cmd(), &begin, VK_SUBPASS_CONTENTS_INLINE);
            if (const std::optional<VkClearValue> clear = ctx.lostContentsClear(d.target)) {
                const VkClearAttachment attachment{VK_IMAGE_ASPECT_COLOR_BIT, 0, *clear};
                const VkClearRect rect{{{0, 0}, extent}, 0, 1};
                vkCmdClearAttachments(ctx.cmd(), 1, &attachment, 1, &rect);
            }
            ImGui_ImplVulkan_RenderDrawData(drawData, ctx.cmd());
            vkCmdEndRenderPass(ctx.cmd());
        });
    return data.target;
}

}  // namespace candela::ui
