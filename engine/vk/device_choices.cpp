#include "vk/device_choices.h"

#include "shader/shader_library.h"

#include <map>

namespace candela::vk {
namespace {

using namespace format_feature;

// A computed map: written as a storage image, sampled with linear filtering.
constexpr VkFormatFeatureFlags2 kComputedMap = kSampled | kLinear | kStorage;

// `preferred` if it has `required`, else `fallback` (noted in `choices`).
VkFormat pick(const DeviceCaps& caps, const char* what, VkFormat preferred, VkFormat fallback,
              VkFormatFeatureFlags2 required, DeviceChoices& choices) {
    if (caps.supports(preferred, required)) return preferred;
    choices.fallbacks.push_back(std::string(what) + ": " + formatName(fallback) + " instead of " + formatName(preferred) +
                                " (no " + formatFeatureNames(required & ~caps.formatFeatures(preferred)) + ")");
    return fallback;
}

// What the visibility path needs that the device lacks, or "".
std::string visibilityUnsupported(const DeviceCaps& caps) {
    if (!caps.features.geometryShader) return "geometryShader, for gl_PrimitiveID in the fragment stage";
    if (!caps.supports(VK_FORMAT_R32G32_UINT, kSampled | kColor))
        return "R32G32_UINT as a sampled colour attachment (the visibility image)";
    std::vector<shader::ShaderReflection> shading;
    for (const char* name : {"visibility_shade_layers.comp"}) shading.push_back(shader::reflectSpirv(shader::shaderSpirv(name), name));
    const shader::ShaderReflection merged = shader::mergeReflections(shading);
    if (const std::string over = descriptorLimitViolation(merged.bindings, merged.pushConstants.size, caps); !over.empty())
        return "more than the device's limits for its compute shading: " + over;
    return {};
}

}  // namespace

DeviceChoices chooseForDevice(const DeviceCaps& caps) {
    DeviceChoices c;
    c.floatCube = pick(caps, "environment cube", VK_FORMAT_R32G32B32A32_SFLOAT, VK_FORMAT_R16G16B16A16_SFLOAT,
                       kComputedMap, c);
    c.sheenLut = pick(caps, "sheen LUT", VK_FORMAT_R32_SFLOAT, VK_FORMAT_R16G16B16A16_SFLOAT, kComputedMap, c);
    c.brdfLut = pick(caps, "BRDF LUT", VK_FORMAT_R16G16_SFLOAT, VK_FORMAT_R16G16B16A16_SFLOAT, kComputedMap, c);
    std::vector<shader::ShaderReflection> layered;
    for (const char* name : {"forward_layers.vert", "forward_layers.frag"})
        layered.push_back(shader::reflectSpirv(shader::shaderSpirv(name), name));
    const shader::ShaderReflection generic = shader::mergeReflections(layered);
    if (const std::string over = descriptorLimitViolation(generic.bindings, generic.pushConstants.size, caps); !over.empty()) {
        c.specializeLayeredProgram = true;
        c.fallbacks.push_back("layered materials: a program per layer combination, declaring only its layers' textures "
                              "(the program with every layer has " + over + ")");
    }
    c.cubeBordersNeedADraw = caps.driver == VK_DRIVER_ID_GOOGLE_SWIFTSHADER;
    if (c.cubeBordersNeedADraw)
        c.fallbacks.push_back("IBL precompute: a draw binds the environment cube after compute writes it, so that "
                              "SwiftShader refreshes the face borders its filtering reads");
    c.visibilityUnsupported = visibilityUnsupported(caps);
    if (!c.visibilityUnsupported.empty()) c.fallbacks.push_back("shading: the forward path only (the visibility path needs " + c.visibilityUnsupported + ")");
    return c;
}

std::string missingCapability(const DeviceCaps& caps) {
    struct Need {
        VkFormat format;
        VkFormatFeatureFlags2 features;
        const char* why;
    };
    static constexpr Need kNeeds[] = {
        {VK_FORMAT_R16G16B16A16_SFLOAT, kSampled | kLinear | kStorage | kColor | kBlend,
         "the HDR image, the specular maps and the fallback formats"},
        {VK_FORMAT_R8G8B8A8_SRGB, kSampled | kLinear | kColor | kBlend, "colour textures and the tonemapped image"},
        {VK_FORMAT_R8G8B8A8_UNORM, kSampled | kLinear | kColor, "data textures"},
        {VK_FORMAT_R32G32B32A32_SFLOAT, kSampled | kStorage | kColor, "the reference environment and BRDF probes"},
        {VK_FORMAT_D32_SFLOAT, kDepth, "the depth buffer"},
    };
    for (const Need& n : kNeeds)
        if (!caps.supports(n.format, n.features))
            return formatName(n.format) + " lacks " + formatFeatureNames(n.features & ~caps.formatFeatures(n.format)) +
                   " (needed for " + n.why + ")";
    if (caps.limits.maxBoundDescriptorSets < 4)
        return "maxBoundDescriptorSets " + std::to_string(caps.limits.maxBoundDescriptorSets) + " < 4";
    return {};
}

std::string descriptorLimitViolation(const std::vector<shader::DescriptorBinding>& bindings, uint32_t pushConstantBytes,
                                     const DeviceCaps& caps) {
    const DeviceLimits& l = caps.limits;
    if (pushConstantBytes > l.maxPushConstantsSize)
        return std::to_string(pushConstantBytes) + " bytes of push constants, the device allows " +
               std::to_string(l.maxPushConstantsSize) + " (maxPushConstantsSize)";
    uint32_t sets = 0;
    for (const shader::DescriptorBinding& b : bindings) sets = std::max(sets, b.set + 1);
    if (sets > l.maxBoundDescriptorSets)
        return std::to_string(sets) + " descriptor sets, the device allows " + std::to_string(l.maxBoundDescriptorSets) +
               " (maxBoundDescriptorSets)";

    struct Counts {
        uint32_t samplers = 0, sampledImages = 0, storageBuffers = 0, storageImages = 0, uniformBuffers = 0, resources = 0;
    };
    std::map<VkShaderStageFlagBits, Counts> perStage;
    for (const shader::DescriptorBinding& b : bindings)
        for (uint32_t bit = 1; bit <= VK_SHADER_STAGE_COMPUTE_BIT; bit <<= 1) {
            if (!(b.stages & bit)) continue;
            Counts& c = perStage[static_cast<VkShaderStageFlagBits>(bit)];
            switch (b.type) {
                case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: c.samplers += b.count; c.sampledImages += b.count; break;
                case VK_DESCRIPTOR_TYPE_SAMPLER: c.samplers += b.count; break;
                case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE: c.sampledImages += b.count; break;
                case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: c.storageBuffers += b.count; break;
                case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: c.storageImages += b.count; break;
                case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: c.uniformBuffers += b.count; break;
                default: break;
            }
            if (b.type != VK_DESCRIPTOR_TYPE_SAMPLER) c.resources += b.count;
        }
    for (const auto& [stage, c] : perStage) {
        const std::string where = stage == VK_SHADER_STAGE_VERTEX_BIT     ? "vertex"
                                  : stage == VK_SHADER_STAGE_FRAGMENT_BIT ? "fragment"
                                  : stage == VK_SHADER_STAGE_COMPUTE_BIT  ? "compute"
                                                                          : "a";
        const auto over = [&](uint32_t count, uint32_t limit, const char* what, const char* name) {
            return count > limit ? std::to_string(count) + " " + what + " in the " + where + " stage, the device allows " +
                                       std::to_string(limit) + " (" + name + ")"
                                 : std::string();
        };
        for (const std::string& v :
             {over(c.samplers, l.maxPerStageDescriptorSamplers, "samplers", "maxPerStageDescriptorSamplers"),
              over(c.sampledImages, l.maxPerStageDescriptorSampledImages, "sampled images",
                   "maxPerStageDescriptorSampledImages"),
              over(c.storageBuffers, l.maxPerStageDescriptorStorageBuffers, "storage buffers",
                   "maxPerStageDescriptorStorageBuffers"),
              over(c.storageImages, l.maxPerStageDescriptorStorageImages, "storage images",
                   "maxPerStageDescriptorStorageImages"),
              over(c.uniformBuffers, l.maxPerStageDescriptorUniformBuffers, "uniform buffers",
                   "maxPerStageDescriptorUniformBuffers"),
              over(c.resources, l.maxPerStageResources, "resources", "maxPerStageResources")})
            if (!v.empty()) return v;
    }
    return {};
}

}  // namespace candela::vk
