#include "vk/context.h"

#include "core/log.h"
#include "vk/check.h"
#include "vk/device_choices.h"
#include "vk/device_select.h"
#include "vk/library_pin.h"
#include "vk/named_drivers.h"
#include "vk/pipeline_cache_file.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <set>

namespace candela::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool envFlag(const char* name) {
    const char* value = std::getenv(name);
    return value && *value && std::strcmp(value, "0") != 0;
}

std::string versionString(uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." + std::to_string(VK_API_VERSION_MINOR(version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(version));
}

std::vector<VkQueueFamilyProperties> queueFamilies(VkPhysicalDevice device) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    return families;
}

// Which queue families can present (empty when presentation is not needed).
std::vector<bool> presentFamilies(VkInstance instance, VkPhysicalDevice device, const PresentSupportFn& presentSupport) {
    std::vector<bool> present;
    if (!presentSupport) return present;
    const uint32_t count = static_cast<uint32_t>(queueFamilies(device).size());
    for (uint32_t family = 0; family < count; ++family) present.push_back(presentSupport(instance, device, family));
    return present;
}

// Why `device`, whose capabilities seen through the device profile are `caps`, cannot run
// Candela, or "" if it can.
std::string unsuitableReason(VkInstance instance, VkPhysicalDevice device, const PresentSupportFn& presentSupport,
                             const DeviceCaps& caps) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device, &properties);
    if (properties.apiVersion < VK_API_VERSION_1_3) return "Vulkan " + versionString(properties.apiVersion) + " < 1.3";
    VkPhysicalDeviceVulkan13Features features13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features features12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                                .pNext = &features13};
    VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &features12};
    vkGetPhysicalDeviceFeatures2(device, &features);
    if (!features12.separateDepthStencilLayouts) return "no separateDepthStencilLayouts";
    if (!features13.dynamicRendering) return "no dynamicRendering";
    if (!features13.synchronization2) return "no synchronization2";
    if (!features13.maintenance4) return "no maintenance4";
    if (!features13.shaderDemoteToHelperInvocation) return "no shaderDemoteToHelperInvocation";
    if (presentSupport && !caps.extensions.swapchain) return "no VK_KHR_swapchain";
    if (std::string missing = missingCapability(caps); !missing.empty()) return missing;
    try {
        chooseQueueFamilies(queueFamilies(device), presentFamilies(instance, device, presentSupport));
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

}  // namespace

Context::InstanceOwner::~InstanceOwner() {
    if (handle) vkDestroyInstance(handle, nullptr);
}
Context::MessengerOwner::~MessengerOwner() {
    if (!handle) return;
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance, handle, nullptr);
}
Context::DeviceOwner::~DeviceOwner() {
    if (handle) vkDestroyDevice(handle, nullptr);
}

Context::Context(const ContextDesc& desc)
    : mValidation(desc.validation || envFlag("CANDELA_VALIDATE")),
      mPrintValidation(desc.printValidationMessages),
      mOnValidation(desc.onValidationMessage),
      mProfile(desc.profile ? *desc.profile : deviceProfileFromEnvironment()) {
    const auto step = [](const char* part, auto&& run) {
        try {
            run();
        } catch (const UserError&) {
            throw;
        } catch (const std::exception& e) {
            throw std::runtime_error(std::string("Vulkan start-up failed in ") + part + ": " + e.what());
        }
    };
    step("instance creation", [&] { createInstance(desc); });
    step("device selection", [&] { pickPhysicalDevice(desc); });
    step("device creation", [&] { createDevice(desc); });
    step("memory allocator", [&] {
        mAllocator = std::make_unique<MemoryAllocator>(mPhysicalDevice, mDevice.handle, mCaps.memoryTypeMask);
        mAllocator->setBudget(desc.deviceMemoryBudget);
        mAllocator->useHeapBudgets(mCaps.extensions.memoryBudget);
        mAllocator->useHugePages(mProperties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU);
    });
    step("pipeline cache", [&] {
        mPipelineCache = std::make_unique<PipelineCacheFile>(mDevice.handle, mProperties, desc.pipelineCacheFolder);
    });
}

Context::~Context() {
    waitIdleAndCollect();
    if (mLiveObjects.load() != 0)
        log::warn("vk::Context destroyed with " + std::to_string(mLiveObjects.load()) + " live Vulkan objects");
}

void Context::createInstance(const ContextDesc& desc) {
    addNamedDriver(effectiveDeviceSelector(desc.deviceSelector));
    // The driver and layers loaded from here on stay loaded (vk/library_pin.h); noted before the
    // first loader call, which may load them already.
    const LibraryPin pin;
    uint32_t layerCount = 0;
    VK_CHECK(vkEnumerateInstanceLayerProperties(&layerCount, nullptr));
    std::vector<VkLayerProperties> layers(layerCount);
    VK_CHECK(vkEnumerateInstanceLayerProperties(&layerCount, layers.data()));
    uint32_t extensionCount = 0;
    VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &extensionCount, nullptr));
    std::vector<VkExtensionProperties> available(extensionCount);
    VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &extensionCount, available.data()));
    const auto hasExtension = [&](const char* name) {
        return std::any_of(available.begin(), available.end(),
                           [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
    };

    std::vector<const char*> enabledLayers;
    std::vector<const char*> extensions;
    for (const std::string& e : desc.instanceExtensions) extensions.push_back(e.c_str());
    if (mValidation) {
        const bool found = std::any_of(layers.begin(), layers.end(), [](const VkLayerProperties& l) {
            return std::strcmp(l.layerName, kValidationLayer) == 0;
        });
        if (!found)
            throw UserError("validation requested but VK_LAYER_KHRONOS_validation is not installed "
                            "(Debian package vulkan-validationlayers)");
        enabledLayers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    }
    mDebugUtils = hasExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME) || mValidation;
    if (mDebugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    VkInstanceCreateFlags flags = 0;
    if (hasExtension(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
        // Lets portability drivers (MoltenVK) be enumerated; harmless elsewhere.
        extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
        flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    }

    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT,
                                                    VK_VALIDATION_FEATURE_ENABLE_BEST_PRACTICES_EXT};
    const bool bestPractices = desc.bestPractices || envFlag("CANDELA_BEST_PRACTICES");
    const VkValidationFeaturesEXT validationFeatures{
        .sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT,
        .enabledValidationFeatureCount = bestPractices ? 2u : 1u,
        .pEnabledValidationFeatures = enables};
    const VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .pNext = mValidation ? &validationFeatures : nullptr,
        .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
        .pfnUserCallback = &Context::debugCallback,
        .pUserData = this};
    const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                                .pApplicationName = "candela",
                                .applicationVersion = VK_MAKE_API_VERSION(0, 0, 1, 0),
                                .pEngineName = "candela",
                                .engineVersion = VK_MAKE_API_VERSION(0, 0, 1, 0),
                                .apiVersion = VK_API_VERSION_1_3};
    const VkInstanceCreateInfo info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                    // Chaining the messenger info also reports messages from instance creation.
                                    .pNext = mDebugUtils ? &messengerInfo : nullptr,
                                    .flags = flags,
                                    .pApplicationInfo = &app,
                                    .enabledLayerCount = static_cast<uint32_t>(enabledLayers.size()),
                                    .ppEnabledLayerNames = enabledLayers.data(),
                                    .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
                                    .ppEnabledExtensionNames = extensions.data()};
    VK_CHECK(vkCreateInstance(&info, nullptr, &mInstance.handle));
    pin.pinNew();
    for (const char* l : enabledLayers) mReport.enabledLayers.emplace_back(l);

    if (mDebugUtils) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(mInstance.handle, "vkCreateDebugUtilsMessengerEXT"));
        VkDebugUtilsMessengerCreateInfoEXT plain = messengerInfo;
        plain.pNext = nullptr;
        mMessenger.instance = mInstance.handle;
        if (create) VK_CHECK(create(mInstance.handle, &plain, nullptr, &mMessenger.handle));
    }
}

void Context::pickPhysicalDevice(const ContextDesc& desc) {
    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(mInstance.handle, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(mInstance.handle, &count, devices.data()));
    std::vector<DeviceCandidate> candidates;
    std::vector<DeviceCaps> caps;  // each device's, seen through the profile
    for (VkPhysicalDevice device : devices) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(device, &properties);
        caps.push_back(narrowCaps(queryDeviceCaps(device), mProfile));
        candidates.push_back({properties.deviceName, properties.deviceType, properties.apiVersion,
                              unsuitableReason(mInstance.handle, device, desc.presentSupport, caps.back())});
    }
    const DeviceChoice choice = chooseDevice(candidates, effectiveDeviceSelector(desc.deviceSelector),
                                             desc.deviceSelector.empty() ? "CANDELA_DEVICE" : "--device");
    mPhysicalDevice = devices[choice.index];
    vkGetPhysicalDeviceProperties(mPhysicalDevice, &mProperties);
    mCaps = std::move(caps[choice.index]);
    mChoices = chooseForDevice(mCaps);
    mReport.profile = options::deviceProfileName(mProfile);
    mReport.name = mProperties.deviceName;
    mReport.type = deviceTypeName(mProperties.deviceType);
    mReport.reason = choice.reason;
    mReport.apiVersion = mProperties.apiVersion;
    VkPhysicalDeviceDriverProperties driver{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 properties2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &driver};
    vkGetPhysicalDeviceProperties2(mPhysicalDevice, &properties2);
    mReport.driverName = driver.driverName;
    mReport.driverInfo = driver.driverInfo;
}

void Context::createDevice(const ContextDesc& desc) {
    const std::vector<VkQueueFamilyProperties> families = queueFamilies(mPhysicalDevice);
    const QueueFamilyChoice queues =
        chooseQueueFamilies(families, presentFamilies(mInstance.handle, mPhysicalDevice, desc.presentSupport));

    const float priority = 1.0f;
    std::vector<VkDeviceQueueCreateInfo> queueInfos;
    for (uint32_t family : std::set<uint32_t>{queues.graphics, queues.compute, queues.transfer})
        queueInfos.push_back({.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                              .queueFamilyIndex = family,
                              .queueCount = 1,
                              .pQueuePriorities = &priority});

    VkPhysicalDeviceVulkan13Features features13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                                .shaderDemoteToHelperInvocation = VK_TRUE,
                                                .synchronization2 = VK_TRUE,
                                                .dynamicRendering = VK_TRUE,
                                                .maintenance4 = VK_TRUE};
    // The depth buffer's layouts (DEPTH_ATTACHMENT_OPTIMAL, DEPTH_READ_ONLY_OPTIMAL) need it.
    VkPhysicalDeviceVulkan12Features features12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                                .pNext = &features13,
                                                .separateDepthStencilLayouts = VK_TRUE};
    VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &features12};
    // Demote (not discard) for the alpha test: derivatives and implicit-LOD sampling stay defined
    // in the quad after it (required by Vulkan 1.3).
    mReport.enabledFeatures = {"dynamicRendering", "synchronization2", "maintenance4", "shaderDemoteToHelperInvocation",
                               "separateDepthStencilLayouts"};
    // Optional features: enabled when the caps (narrowed by the profile) have them.
    const DeviceFeatures& optional = mCaps.features;
    const auto enable = [&](bool available, VkBool32& feature, const char* name) {
        if (!available) return;
        feature = VK_TRUE;
        mReport.enabledFeatures.emplace_back(name);
    };
    enable(optional.samplerAnisotropy, features.features.samplerAnisotropy, "samplerAnisotropy");
    enable(optional.alphaToOne, features.features.alphaToOne, "alphaToOne");
    enable(optional.fullDrawIndexUint32, features.features.fullDrawIndexUint32, "fullDrawIndexUint32");
    enable(optional.shaderStorageImageExtendedFormats, features.features.shaderStorageImageExtendedFormats,
           "shaderStorageImageExtendedFormats");
    enable(optional.geometryShader, features.features.geometryShader, "geometryShader");
    mAlphaToOne = optional.alphaToOne;

    std::vector<const char*> extensions;
    if (desc.presentSupport) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    // A portability driver (MoltenVK) must have VK_KHR_portability_subset enabled when it has it.
    if (mCaps.extensions.portabilitySubset) extensions.push_back("VK_KHR_portability_subset");
    if (mCaps.extensions.memoryBudget) extensions.push_back(VK_EXT_MEMORY_BUDGET_EXTENSION_NAME);
    for (const char* e : extensions) mReport.enabledExtensions.emplace_back(e);
    const VkDeviceCreateInfo info{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                  .pNext = &features,
                                  .queueCreateInfoCount = static_cast<uint32_t>(queueInfos.size()),
                                  .pQueueCreateInfos = queueInfos.data(),
                                  .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
                                  .ppEnabledExtensionNames = extensions.data()};
    const LibraryPin pin;  // and what the driver loads for a device
    VK_CHECK(vkCreateDevice(mPhysicalDevice, &info, nullptr, &mDevice.handle));
    pin.pinNew();

    mGraphics = {VK_NULL_HANDLE, queues.graphics};
    mCompute = {VK_NULL_HANDLE, queues.compute};
    mTransfer = {VK_NULL_HANDLE, queues.transfer};
    for (QueueInfo* q : {&mGraphics, &mCompute, &mTransfer}) vkGetDeviceQueue(mDevice.handle, q->family, 0, &q->queue);

    mReport.graphicsFamily = queues.graphics;
    mReport.computeFamily = queues.compute;
    mReport.transferFamily = queues.transfer;
    mReport.timestampValidBits = families[queues.graphics].timestampValidBits;
    mReport.timestampPeriodNs = mReport.timestampValidBits ? mProperties.limits.timestampPeriod : 0.0f;

    if (mDebugUtils) {
        mSetObjectName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
            vkGetInstanceProcAddr(mInstance.handle, "vkSetDebugUtilsObjectNameEXT"));
        mCmdBeginLabel = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
            vkGetInstanceProcAddr(mInstance.handle, "vkCmdBeginDebugUtilsLabelEXT"));
        mCmdEndLabel = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
            vkGetInstanceProcAddr(mInstance.handle, "vkCmdEndDebugUtilsLabelEXT"));
    }
}

VkBool32 VKAPI_PTR Context::debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                          VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data,
                                          void* user) {
    auto* self = static_cast<Context*>(user);
    ValidationMessage message{severity, data && data->pMessage ? data->pMessage : "(no message)"};
    ++self->mValidationCount;
    {
        std::lock_guard lock(self->mValidationMutex);
        self->mValidationMessages.push_back(message);
    }
    if (self->mPrintValidation)
        log::error(std::string(severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "validation error: "
                                                                                        : "validation warning: ") +
                   message.text);
    if (self->mOnValidation) self->mOnValidation(message);
    return VK_FALSE;
}

std::vector<ValidationMessage> Context::validationMessages() const {
    std::lock_guard lock(mValidationMutex);
    return mValidationMessages;
}

VkPipelineCache Context::pipelineCache() const { return mPipelineCache ? mPipelineCache->handle() : VK_NULL_HANDLE; }

void Context::defer(std::function<void()> destroy) {
    std::lock_guard lock(mDeferredMutex);
    mDeferred.emplace_back(mFrame.load(), std::move(destroy));
}

void Context::collect(uint64_t completedFrame) {
    // Destructors may defer more work; swap out first so new entries are kept for later.
    std::vector<std::pair<uint64_t, std::function<void()>>> pending, later;
    {
        std::lock_guard lock(mDeferredMutex);
        pending.swap(mDeferred);
    }
    for (auto& [frame, destroy] : pending) {
        if (frame <= completedFrame)
            destroy();
        else
            later.emplace_back(frame, std::move(destroy));
    }
    // The ones not due yet stay ahead of those deferred meanwhile, in the order they came.
    std::lock_guard lock(mDeferredMutex);
    mDeferred.insert(mDeferred.begin(), std::make_move_iterator(later.begin()), std::make_move_iterator(later.end()));
}

void Context::waitIdleAndCollect() {
    if (!mDevice.handle) return;
    VK_CHECK(vkDeviceWaitIdle(mDevice.handle));
    const auto anyDeferred = [&] {
        std::lock_guard lock(mDeferredMutex);
        return !mDeferred.empty();
    };
    while (anyDeferred()) collect(~0ull);
    // A quiet point (scene or environment change, shutdown): give empty memory blocks back.
    if (mAllocator) mAllocator->trim();
}

void Context::setName(VkObjectType type, uint64_t object, const char* name) const {
    if (!mSetObjectName || !name || !object) return;
    const VkDebugUtilsObjectNameInfoEXT info{.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT,
                                             .objectType = type,
                                             .objectHandle = object,
                                             .pObjectName = name};
    VK_CHECK(mSetObjectName(mDevice.handle, &info));
}

void Context::beginLabel(VkCommandBuffer cmd, const char* name) const {
    if (!mCmdBeginLabel) return;
    const VkDebugUtilsLabelEXT label{.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT, .pLabelName = name};
    mCmdBeginLabel(cmd, &label);
}

void Context::endLabel(VkCommandBuffer cmd) const {
    if (mCmdEndLabel) mCmdEndLabel(cmd);
}

}  // namespace candela::vk
