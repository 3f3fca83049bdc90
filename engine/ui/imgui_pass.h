#pragma once
// ImGui pass (graphics): draws the current Dear ImGui frame (ImGui::GetDrawData()) over the
// finished 8-bit frame with Dear ImGui's own Vulkan backend. Present only when a window is (the
// viewer); headless captures have no UI.
//
// Debian's Dear ImGui (1.86) draws inside a VkRenderPass, so the pass owns one (load and store,
// colour-attachment layout before and after: the graph places the barriers and transitions around
// it) and a framebuffer per frame, dropped through the deferred deletion queue.
//
// Preconditions: an ImGui context exists and its platform backend (GLFW) is initialised before
// the pass is created; the pass is destroyed before them. Owns the backend's Vulkan state.

#include "graph/render_graph.h"
#include "vk/handle.h"

namespace candela::ui {

class ImGuiPass {
public:
    // `minImageCount`/`imageCount`: of the swapchain (the backend keeps one vertex buffer per
    // image, so it must be at least the number of frames in flight). Uploads the font atlas.
    ImGuiPass(vk::Context& context, VkFormat format, uint32_t minImageCount, uint32_t imageCount);
    ~ImGuiPass();
    ImGuiPass(const ImGuiPass&) = delete;
    ImGuiPass& operator=(const ImGuiPass&) = delete;

    // Adds the pass drawing ImGui's last rendered frame over `target` (format as constructed);
    // returns the target's new version. Precondition: ImGui::Render() was called this frame.
    graph::TextureId add(graph::RenderGraph& graph, graph::TextureId target);

    VkFormat format() const { return mFormat; }

private:
    vk::Context& mContext;
    VkFormat mFormat;
    VkRenderPass mRenderPass = VK_NULL_HANDLE;
    vk::DescriptorPool mDescriptorPool;
};

}  // namespace candela::ui
