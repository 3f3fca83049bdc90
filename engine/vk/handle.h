#pragma once
// Handle<T>: move-only owner of one Vulkan object destroyed with vkDestroyXxx(device, handle, nullptr).
// Destruction goes through Context::defer, so an object may be dropped while frames in flight
// still use it. Used for samplers, views, layouts, pipelines, pools, fences, semaphores and query pools.

#include "vk/context.h"

#include <vulkan/vulkan_core.h>

#include <utility>

namespace candela::vk {

template <class T, void(VKAPI_PTR* Destroy)(VkDevice, T, const VkAllocationCallbacks*)>
class Handle {
public:
    Handle() = default;
    // Adopts `handle` (created by the caller on context's device) and counts it as live.
    Handle(Context& context, T handle) : mContext(&context), mHandle(handle) {
        if (mHandle) context.countCreated();
    }
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept
        : mContext(std::exchange(other.mContext, nullptr)), mHandle(std::exchange(other.mHandle, T{})) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            mContext = std::exchange(other.mContext, nullptr);
            mHandle = std::exchange(other.mHandle, T{});
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    T get() const { return mHandle; }
    explicit operator bool() const { return mHandle != T{}; }

    // Hands the object to the deferred deletion queue.
    void reset() {
        if (!mHandle) return;
        Context* context = mContext;
        context->defer([context, handle = mHandle] {
            Destroy(context->device(), handle, nullptr);
            context->countDestroyed();
        });
        mHandle = T{};
    }

private:
    Context* mContext = nullptr;
    T mHandle{};
};

using Sampler = Handle<VkSampler, vkDestroySampler>;
using ImageViewHandle = Handle<VkImageView, vkDestroyImageView>;
using ShaderModule = Handle<VkShaderModule, vkDestroyShaderModule>;
using PipelineLayout = Handle<VkPipelineLayout, vkDestroyPipelineLayout>;
using DescriptorSetLayout = Handle<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using DescriptorPool = Handle<VkDescriptorPool, vkDestroyDescriptorPool>;
using PipelineHandle = Handle<VkPipeline, vkDestroyPipeline>;
using CommandPool = Handle<VkCommandPool, vkDestroyCommandPool>;
using Fence = Handle<VkFence, vkDestroyFence>;
using Semaphore = Handle<VkSemaphore, vkDestroySemaphore>;
using QueryPool = Handle<VkQueryPool, vkDestroyQueryPool>;

}  // namespace candela::vk
