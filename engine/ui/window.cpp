#include "ui/window.h"

#include "vk/check.h"
#include "vk/context.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <string>
#include <utility>

namespace candela::ui {

namespace {

int gWindows = 0;
std::string gLastError;

void onGlfwError(int, const char* description) { gLastError = description ? description : "unknown GLFW error"; }

void releaseGlfw() {
    if (--gWindows == 0) glfwTerminate();
}

// Starts GLFW for one more user (WindowSystem or Window); each is released with releaseGlfw.
void initGlfw() {
    if (gWindows++ == 0) {
        glfwSetErrorCallback(onGlfwError);
        if (!glfwInit()) {
            --gWindows;
            throw UserError("cannot open a window: " + (gLastError.empty() ? std::string("GLFW failed to start") : gLastError) +
                            " (is a display available? for headless use, `candela render`)");
        }
    }
    if (!glfwVulkanSupported()) {
        releaseGlfw();
        throw UserError("cannot open a window: GLFW found no Vulkan loader with window-system support");
    }
}

Window* self(GLFWwindow* window) { return static_cast<Window*>(glfwGetWindowUserPointer(window)); }

}  // namespace

WindowSystem::WindowSystem() { initGlfw(); }

WindowSystem::~WindowSystem() { releaseGlfw(); }

void WindowSystem::addTo(vk::ContextDesc& desc) const {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw UserError("cannot open a window: " + gLastError);
    desc.instanceExtensions.insert(desc.instanceExtensions.end(), names, names + count);
    desc.presentSupport = [](VkInstance instance, VkPhysicalDevice device, uint32_t family) {
        return glfwGetPhysicalDevicePresentationSupport(instance, device, family) == GLFW_TRUE;
    };
}

Window::Window(const WindowDesc& desc) {
    initGlfw();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    mWindow = glfwCreateWindow(int(desc.width), int(desc.height), desc.title.c_str(), nullptr, nullptr);
    if (!mWindow) {
        const std::string error = gLastError;
        releaseGlfw();
        throw UserError("cannot open a window: " + error);
    }
    glfwSetWindowUserPointer(mWindow, this);
    // Installed before ImGui's GLFW backend, which chains to them.
    glfwSetDropCallback(mWindow, [](GLFWwindow* window, int count, const char** paths) {
        for (int i = 0; i < count; ++i) self(window)->mDropped.emplace_back(paths[i]);
    });
    glfwSetScrollCallback(mWindow, [](GLFWwindow* window, double, double y) { self(window)->mScroll += float(y); });
    glfwSetKeyCallback(mWindow, [](GLFWwindow* window, int key, int, int action, int) {
        if (action == GLFW_PRESS) self(window)->mKeys.push_back(key);
    });
}

Window::~Window() {
    glfwDestroyWindow(mWindow);
    releaseGlfw();
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    const VkResult result = glfwCreateWindowSurface(instance, mWindow, nullptr, &surface);
    if (result != VK_SUCCESS) throw vk::VulkanError("cannot create a window surface: " + gLastError, result);
    return surface;
}

VkExtent2D Window::framebufferSize() const {
    if (minimized()) return {0, 0};
    int width = 0, height = 0;
    glfwGetFramebufferSize(mWindow, &width, &height);
    return {uint32_t(std::max(width, 0)), uint32_t(std::max(height, 0))};
}

bool Window::minimized() const { return glfwGetWindowAttrib(mWindow, GLFW_ICONIFIED) == GLFW_TRUE; }
bool Window::shouldClose() const { return glfwWindowShouldClose(mWindow) == GLFW_TRUE; }
void Window::requestClose() { glfwSetWindowShouldClose(mWindow, GLFW_TRUE); }
void Window::pollEvents() { glfwPollEvents(); }
void Window::waitEvents() { glfwWaitEventsTimeout(0.25); }

std::vector<std::string> Window::takeDroppedFiles() { return std::exchange(mDropped, {}); }
float Window::takeScroll() { return std::exchange(mScroll, 0.0f); }
std::vector<int> Window::takeKeyPresses() { return std::exchange(mKeys, {}); }

glm::vec2 Window::cursor() const {
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(mWindow, &x, &y);
    return {float(x), float(y)};
}

bool Window::mouseButton(int button) const { return glfwGetMouseButton(mWindow, button) == GLFW_PRESS; }

void Window::setSize(uint32_t width, uint32_t height) { glfwSetWindowSize(mWindow, int(width), int(height)); }
void Window::iconify() { glfwIconifyWindow(mWindow); }
void Window::restore() { glfwRestoreWindow(mWindow); }

}  // namespace candela::ui
