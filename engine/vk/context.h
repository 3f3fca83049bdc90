#pragma once
// vk::Context: the Vulkan instance, the chosen device and its queues, the memory allocator and the
// deferred deletion queue. One per process (tests may create several in sequence).
//
// Start-up runs in a fixed order (instance → debug messenger → physical device → device →
// allocator); each part is a member in that order, so a failure unwinds what was started and
// destruction runs in reverse. The error names the part that failed.

#include "vk/device_caps.h"
#include "vk/device_choices.h"
#include "vk/profile_caps.h"
#include "vk/memory.h"

#include <vulkan/vulkan_core.h>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace candela::vk {

class PipelineCacheFile;

struct ValidationMessage {
    VkDebugUtilsMessageSeverityFlagBitsEXT severity;
    std::string text;
};

// Whether queue family `family` of `device` can present to the window system in use
// (e.g. glfwGetPhysicalDevicePresentationSupport).
using PresentSupportFn = std::function<bool(VkInstance instance, VkPhysicalDevice device, uint32_t family)>;

struct ContextDesc {
    // Khronos validation layer with synchronization validation. Also on when CANDELA_VALIDATE=1.
    bool validation = false;
    // With validation: the layer's best-practices checks too (performance warnings such as
    // barriers wider than they need to be). Also on when CANDELA_BEST_PRACTICES=1.
    bool bestPractices = false;
    // "" picks the best device (or the one CANDELA_DEVICE selects); an index or a case-insensitive
    // name substring picks one (--device). One naming SwiftShader adds its driver (vk/named_drivers.h).
    std::string deviceSelector;
    // Instance extensions a window system needs (e.g. from glfwGetRequiredInstanceExtensions).
    std::vector<std::string> instanceExtensions;
    // Caps the device memory Candela allocates (bytes; 0: none), to simulate small devices
    // (--memory-budget). Beyond it allocations fail with OutOfDeviceMemory.
    uint64_t deviceMemoryBudget = 0;
    // Narrows Candela's view of the device to a profile (--device-profile); unset: the profile
    // CANDELA_DEVICE_PROFILE names, else Native.
    std::optional<options::DeviceProfile> profile;
    // Set when frames will be presented to a window: the graphics queue must be able to present,
    // devices without VK_KHR_swapchain are unsuitable, and the extension is enabled.
    PresentSupportFn presentSupport;
    // Called for every validation warning or error (after it is counted and printed).
    std::function<void(const ValidationMessage&)> onValidationMessage;
    // Print validation messages to stderr.
    bool printValidationMessages = true;
    // The folder of the on-disk pipeline cache (vk/pipeline_cache_file.h; the front end's default
    // is the user's cache folder, --pipeline-cache); empty: a cache in memory only, no file.
    std::filesystem::path pipelineCacheFolder;
};

struct QueueInfo {
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t family = ~0u;
};

// What `candela info` prints about the chosen device.
struct DeviceReport {
    std::string name;
    std::string type;
    std::string reason;            // why it was chosen
    uint32_t apiVersion = 0;
    std::string driverName, driverInfo;
    std::string profile;           // the device profile in use ("native" when none)
    std::vector<std::string> enabledFeatures;
    std::vector<std::string> enabledExtensions;
    std::vector<std::string> enabledLayers;
    uint32_t graphicsFamily = 0, computeFamily = 0, transferFamily = 0;
    float timestampPeriodNs = 0;   // 0: the graphics queue has no timestamps
    uint32_t timestampValidBits = 0;
};

class Context {
public:
    explicit Context(const ContextDesc& desc);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return mInstance.handle; }
    VkPhysicalDevice physicalDevice() const { return mPhysicalDevice; }
    VkDevice device() const { return mDevice.handle; }
    const QueueInfo& graphicsQueue() const { return mGraphics; }  // graphics + compute + transfer
    const QueueInfo& computeQueue() const { return mCompute; }    // may be the graphics queue
    const QueueInfo& transferQueue() const { return mTransfer; }  // may be the graphics queue
    const VkPhysicalDeviceProperties& properties() const { return mProperties; }
    const DeviceReport& report() const { return mReport; }
    // What Candela may use of the device, narrowed by the device profile. Every device-dependent
    // choice reads this rather than the driver.
    const DeviceCaps& caps() const { return mCaps; }
    options::DeviceProfile profile() const { return mProfile; }
    // The formats and fallbacks chosen from caps().
    const DeviceChoices& choices() const { return mChoices; }
    MemoryAllocator& allocator() { return *mAllocator; }
    bool validationEnabled() const { return mValidation; }
    // Whether the alphaToOne feature is enabled (alpha to coverage that stores alpha 1).
    bool alphaToOne() const { return mAlphaToOne; }
    // The MSAA sample counts the device can render colour and depth attachments with (bits of 1, 2, 4, 8, ...).
    VkSampleCountFlags attachmentSampleCounts() const { return mCaps.attachmentSampleCounts(); }

    // The pipeline cache every pipeline is created with (internally synchronized: any thread), and
    // its file (written back when the context is destroyed).
    VkPipelineCache pipelineCache() const;
    const PipelineCacheFile& pipelineCacheFile() const { return *mPipelineCache; }
    // The pipelines created since the context was, and the time their vkCreate*Pipelines calls
    // took, summed over the threads that made them (a CPU driver compiles the shaders then:
    // lavapipe's LLVM JIT). Pipeline::compute and ::graphics count themselves; any thread.
    struct PipelineCreation {
        uint64_t count = 0;
        double milliseconds = 0.0;
    };
    PipelineCreation pipelineCreation() const { return {mPipelinesCreated.load(), double(mPipelineNanoseconds.load()) * 1e-6}; }
    void countPipelineCreation(uint64_t nanoseconds) {
        ++mPipelinesCreated;
        mPipelineNanoseconds += nanoseconds;
    }

    // Validation messages (warnings and errors) seen since creation.
    uint32_t validationMessageCount() const { return mValidationCount.load(); }
    std::vector<ValidationMessage> validationMessages() const;

    // Deferred destruction: `destroy` runs once the GPU has finished every frame submitted up to
    // now (see collect). Resource destructors use this, so a resource may be dropped while a
    // frame in flight still uses it. Any thread (a pipeline built on a worker that fails drops
    // its parts there); collect and waitIdleAndCollect run on the thread that submits.
    void defer(std::function<void()> destroy);
    // Number of the frame being recorded; incremented by FrameRing at each submit.
    uint64_t currentFrame() const { return mFrame.load(); }
    void advanceFrame() { ++mFrame; }
    // Runs deferred destructions queued at or before frame `completedFrame`.
    void collect(uint64_t completedFrame);
    // Waits for the device to go idle, runs every deferred destruction and frees empty memory blocks.
    void waitIdleAndCollect();

    // Live Vulkan objects created through the device layer (images, buffers, views, pipelines...).
    // Tests use it to prove that building and destroying resources leaks nothing.
    int64_t liveObjects() const { return mLiveObjects.load(); }
    void countCreated() { ++mLiveObjects; }
    void countDestroyed() { --mLiveObjects; }

    // Gives `object` a debug name (shown by validation messages and debuggers) when available.
    void setName(VkObjectType type, uint64_t object, const char* name) const;
    // Debug labels around command ranges (pass names in captures and validation messages).
    void beginLabel(VkCommandBuffer cmd, const char* name) const;
    void endLabel(VkCommandBuffer cmd) const;

private:
    struct InstanceOwner {
        VkInstance handle = VK_NULL_HANDLE;
        ~InstanceOwner();
    };
    struct MessengerOwner {
        VkInstance instance = VK_NULL_HANDLE;
        VkDebugUtilsMessengerEXT handle = VK_NULL_HANDLE;
        ~MessengerOwner();
    };
    struct DeviceOwner {
        VkDevice handle = VK_NULL_HANDLE;
        ~DeviceOwner();
    };

    void createInstance(const ContextDesc& desc);
    void pickPhysicalDevice(const ContextDesc& desc);
    void createDevice(const ContextDesc& desc);
    static VkBool32 VKAPI_PTR debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                            VkDebugUtilsMessageTypeFlagsEXT types,
                                            const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

    // Members in start-up order: destruction runs in reverse.
    bool mValidation = false;
    bool mAlphaToOne = false;
    bool mPrintValidation = true;
    bool mDebugUtils = false;
    std::function<void(const ValidationMessage&)> mOnValidation;
    options::DeviceProfile mProfile = options::DeviceProfile::Native;
    std::atomic<uint32_t> mValidationCount{0};
    std::atomic<uint64_t> mPipelinesCreated{0}, mPipelineNanoseconds{0};
    mutable std::mutex mValidationMutex;
    std::vector<ValidationMessage> mValidationMessages;
    InstanceOwner mInstance;
    MessengerOwner mMessenger;
    VkPhysicalDevice mPhysicalDevice = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties mProperties{};
    DeviceCaps mCaps;
    DeviceChoices mChoices;
    DeviceReport mReport;
    DeviceOwner mDevice;
    QueueInfo mGraphics, mCompute, mTransfer;
    PFN_vkSetDebugUtilsObjectNameEXT mSetObjectName = nullptr;
    PFN_vkCmdBeginDebugUtilsLabelEXT mCmdBeginLabel = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT mCmdEndLabel = nullptr;
    std::unique_ptr<MemoryAllocator> mAllocator;
    std::unique_ptr<PipelineCacheFile> mPipelineCache;  // written back and destroyed before the device
    std::atomic<int64_t> mLiveObjects{0};
    std::atomic<uint64_t> mFrame{0};
    std::mutex mDeferredMutex;  // guards mDeferred
    std::vector<std::pair<uint64_t, std::function<void()>>> mDeferred;
};

}  // namespace candela::vk
