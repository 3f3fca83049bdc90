#pragma once
// The window system (GLFW) and its windows for Vulkan (no client API): what a device needs to
// present to them (WindowSystem), a window's input as the viewer needs it and its surface
// (Window). GLFW is initialised by the first WindowSystem or Window and terminated with the last.
//
// Threading: GLFW requires the main thread for every call here.

#include <vulkan/vulkan_core.h>

#include <glm/glm.hpp>

#include <string>
#include <vector>

struct GLFWwindow;

namespace candela::vk {
struct ContextDesc;
}

namespace candela::ui {

// The window system, started for as long as this lives. A device that draws to windows is created
// from a context description it has added to, while it lives.
class WindowSystem {
public:
    // Throws UserError naming the cause when no window can be opened (no display, no Vulkan
    // support in GLFW).
    WindowSystem();
    ~WindowSystem();
    WindowSystem(const WindowSystem&) = delete;
    WindowSystem& operator=(const WindowSystem&) = delete;

    // Adds to `desc` the instance extensions the window system needs (VK_KHR_surface and the
    // platform's) and its test of a queue family's presentation support.
    void addTo(vk::ContextDesc& desc) const;
};

struct WindowDesc {
    std::string title = "Candela";
    uint32_t width = 1280;
    uint32_t height = 720;
};

class Window {
public:
    // Throws UserError naming the cause when no window can be opened (no display, no Vulkan
    // support in GLFW).
    explicit Window(const WindowDesc& desc);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // A new surface for the window; the caller owns it (vk::Swapchain takes it).
    VkSurfaceKHR createSurface(VkInstance instance) const;

    GLFWwindow* handle() const { return mWindow; }
    // Framebuffer size in pixels; 0 × 0 while minimized.
    VkExtent2D framebufferSize() const;
    bool minimized() const;
    bool shouldClose() const;
    void requestClose();

    // Processes pending events without blocking / blocking until one arrives (minimized windows).
    void pollEvents();
    void waitEvents();

    // Files dropped on the window since the last call.
    std::vector<std::string> takeDroppedFiles();
    // Scroll-wheel steps since the last call (positive: away from the user).
    float takeScroll();
    // Keys pressed (GLFW_KEY_*) since the last call.
    std::vector<int> takeKeyPresses();
    glm::vec2 cursor() const;
    bool mouseButton(int button) const;

    // Programmatic window control (tests, scripted runs).
    void setSize(uint32_t width, uint32_t height);
    void iconify();
    void restore();

private:
    GLFWwindow* mWindow = nullptr;
    std::vector<std::string> mDropped;
    std::vector<int> mKeys;
    float mScroll = 0.0f;
};

}  // namespace candela::ui
