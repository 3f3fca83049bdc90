#include "vk/pipeline.h"

#include "core/log.h"
#include "shader/shader_library.h"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/device_choices.h"

#include <algorithm>
#include <chrono>

namespace candela::vk {

Program::Program(Context& context, const std::vector<std::string_view>& shaderNames,
                 const ProgramSpecialization& specialization) {
    std::vector<shader::ShaderReflection> reflections, specializedReflections;
    for (std::string_view name : shaderNames) {
        mName += (mName.empty() ? "" : "+") + std::string(name);
        // The SPIR-V and its generation together: a replacement on another thread meanwhile is
        // either wholly in this program or makes it stale.
        const shader::ShaderVersion version = shader::currentShader(name);
        const std::span<const uint32_t> declared = version.spirv;
        if (declared.empty()) throw std::runtime_error("no built-in shader named '" + std::string(name) + "'");
        mSources.emplace_back(std::string(name), version.generation);
        reflections.push_back(shader::reflectSpirv(declared, std::string(name)));
        std::vector<uint32_t> specialized;
        if (!specialization.frozen.empty()) {
            specialized = shader::specializeSpirv(declared, specialization.frozen, std::string(name));
            specializedReflections.push_back(shader::reflectSpirv(specialized, std::string(name)));
        }
        if (!specialization.outputLocations.empty() && reflections.back().stage == VK_SHADER_STAGE_FRAGMENT_BIT)
            specialized = shader::remapOutputLocations(specialized.empty() ? declared : std::span<const uint32_t>(specialized),
                                                       specialization.outputLocations, std::string(name));
        const std::span<const uint32_t> spirv = specialized.empty() ? declared : std::span<const uint32_t>(specialized);
        const VkShaderModuleCreateInfo info{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                            .codeSize = spirv.size_bytes(),
                                            .pCode = spirv.data()};
        VkShaderModule module = VK_NULL_HANDLE;
        VK_CHECK(vkCreateShaderModule(context.device(), &info, nullptr, &module));
        mStages.push_back({reflections.back().stage, ShaderModule(context, module)});
    }
    mReflection = shader::mergeReflections(reflections);
    if (!specializedReflections.empty()) {
        // The specialized sets declare what the specialized code reads; the others keep every binding.
        const shader::ShaderReflection used = shader::mergeReflections(specializedReflections);
        const auto specializedSet = [&](uint32_t set) {
            return std::find(specialization.sets.begin(), specialization.sets.end(), set) != specialization.sets.end();
        };
        std::erase_if(mReflection.bindings, [&](const shader::DescriptorBinding& b) { return specializedSet(b.set); });
        for (const shader::DescriptorBinding& b : used.bindings)
            if (specializedSet(b.set)) mReflection.bindings.push_back(b);
    }
    // A program the device cannot bind is refused here, naming the limit, rather than left to the
    // driver (lavapipe would accept it; a GPU with the limit fails or misrenders).
    if (const std::string over = descriptorLimitViolation(mReflection.bindings, mReflection.pushConstants.size, context.caps());
        !over.empty())
        throw UserError(context.report().name + " (device profile " + context.report().profile + ") cannot run " + mName +
                        ": " + over);

    uint32_t setCount = 0;
    for (const shader::DescriptorBinding& b : mReflection.bindings) setCount = std::max(setCount, b.set + 1);
    std::vector<VkDescriptorSetLayout> rawLayouts;
    for (uint32_t set = 0; set < setCount; ++set) {
        std::vector<VkDescriptorSetLayoutBinding> bindings;
        for (const shader::DescriptorBinding& b : mReflection.bindings)
            if (b.set == set)
                bindings.push_back({.binding = b.binding, .descriptorType = b.type, .descriptorCount = b.count,
                                    .stageFlags = b.stages});
        const VkDescriptorSetLayoutCreateInfo info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                                   .bindingCount = static_cast<uint32_t>(bindings.size()),
                                                   .pBindings = bindings.data()};
        VkDescriptorSetLayout layout = VK_NULL_HANDLE;
        VK_CHECK(vkCreateDescriptorSetLayout(context.device(), &info, nullptr, &layout));
        mSetLayouts.emplace_back(context, layout);
        rawLayouts.push_back(layout);
    }
    const VkPushConstantRange range{.stageFlags = mReflection.pushConstants.stages,
                                    .offset = 0,
                                    .size = mReflection.pushConstants.size};
    const VkPipelineLayoutCreateInfo info{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                          .setLayoutCount = static_cast<uint32_t>(rawLayouts.size()),
                                          .pSetLayouts = rawLayouts.data(),
                                          .pushConstantRangeCount = range.size > 0 ? 1u : 0u,
                                          .pPushConstantRanges = &range};
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreatePipelineLayout(context.device(), &info, nullptr, &layout));
    mLayout = PipelineLayout(context, layout);
}

bool Program::declares(uint32_t set, std::string_view name) const {
    return std::any_of(mReflection.bindings.begin(), mReflection.bindings.end(),
                       [&](const shader::DescriptorBinding& b) { return b.set == set && b.name == name; });
}

bool Program::stale() const {
    for (const auto& [name, generation] : mSources)
        if (shader::shaderGeneration(name) != generation) return true;
    return false;
}

namespace {
// Maps constant_id i to specialization[i].
struct Specialization {
    std::vector<VkSpecializationMapEntry> entries;
    VkSpecializationInfo info{};
    explicit Specialization(const std::vector<uint32_t>& values) {
        for (uint32_t i = 0; i < values.size(); ++i) entries.push_back({i, i * 4u, 4u});
        info = {static_cast<uint32_t>(entries.size()), entries.data(), values.size() * 4u, values.data()};
    }
    const VkSpecializationInfo* get() const { return entries.empty() ? nullptr : &info; }
};
}  // namespace

Pipeline Pipeline::compute(Context& context, std::string_view shaderName, const std::vector<uint32_t>& specialization) {
    const Specialization constants(specialization);
    Pipeline out;
    out.mProgram = Program(context, {shaderName});
    out.mBindPoint = VK_PIPELINE_BIND_POINT_COMPUTE;
    out.mShaderNames = {std::string(shaderName)};
    out.mDesc.specialization = specialization;
    const VkComputePipelineCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage = {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                  .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                  .module = out.mProgram.stages().front().module.get(),
                  .pName = "main",
                  .pSpecializationInfo = constants.get()},
        .layout = out.mProgram.layout()};
    VkPipeline pipeline = VK_NULL_HANDLE;
    const auto start = std::chrono::steady_clock::now();
    VK_CHECK(vkCreateComputePipelines(context.device(), context.pipelineCache(), 1, &info, nullptr, &pipeline));
    context.countPipelineCreation(uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start).count()));
    out.mPipeline = PipelineHandle(context, pipeline);
    return out;
}

ProgramSpecialization programSpecialization(const GraphicsPipelineDesc& desc) {
    ProgramSpecialization out{.sets = desc.specializedSets, .outputLocations = desc.outputLocations};
    for (uint32_t id : desc.frozenConstants) out.frozen.emplace_back(id, desc.specialization.at(id));
    return out;
}

Pipeline Pipeline::graphics(Context& context, std::string_view vertexShader, std::string_view fragmentShader,
                            const GraphicsPipelineDesc& desc) {
    Pipeline out;
    std::vector<std::string_view> shaders{vertexShader};
    if (!fragmentShader.empty()) shaders.push_back(fragmentShader);
    out.mProgram = Program(context, shaders, programSpecialization(desc));
    out.mBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    out.mShaderNames = {std::string(vertexShader), std::string(fragmentShader)};
    out.mDesc = desc;

    const Specialization constants(desc.specialization);
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    for (const Program::Stage& s : out.mProgram.stages())
        stages.push_back({.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                          .stage = s.stage,
                          .module = s.module.get(),
                          .pName = "main",
                          .pSpecializationInfo = constants.get()});
    const VkPipelineVertexInputStateCreateInfo vertexInput{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
        .vertexBindingDescriptionCount = static_cast<uint32_t>(desc.vertexBindings.size()),
        .pVertexBindingDescriptions = desc.vertexBindings.data(),
        .vertexAttributeDescriptionCount = static_cast<uint32_t>(desc.vertexAttributes.size()),
        .pVertexAttributeDescriptions = desc.vertexAttributes.data()};
    const VkPipelineInputAssemblyStateCreateInfo inputAssembly{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO, .topology = desc.topology};
    const VkPipelineViewportStateCreateInfo viewport{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO, .viewportCount = 1, .scissorCount = 1};
    const VkPipelineRasterizationStateCreateInfo raster{.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
                                                        .rasterizerDiscardEnable = desc.rasterizerDiscard,
                                                        .polygonMode = VK_POLYGON_MODE_FILL,
                                                        .cullMode = desc.cullMode,
                                                        .frontFace = desc.frontFace,
                                                        .lineWidth = 1.0f};
    const VkPipelineMultisampleStateCreateInfo multisample{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO, .rasterizationSamples = static_cast<VkSampleCountFlagBits>(desc.samples),
        .alphaToCoverageEnable = desc.alphaToCoverage,
        .alphaToOneEnable = desc.alphaToCoverage};
    const VkPipelineDepthStencilStateCreateInfo depth{.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
                                                      .depthTestEnable = desc.depthTest,
                                                      .depthWriteEnable = desc.depthWrite,
                                                      .depthCompareOp = desc.depthCompare};
    const bool under = desc.blend == BlendMode::Under;
    std::vector<VkPipelineColorBlendAttachmentState> blends(
        desc.colorFormats.size(),
        {.blendEnable = desc.blend != BlendMode::None,
         .srcColorBlendFactor = under ? VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA : VK_BLEND_FACTOR_ONE,
         .dstColorBlendFactor = under ? VK_BLEND_FACTOR_ONE : VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
         .colorBlendOp = VK_BLEND_OP_ADD,
         .srcAlphaBlendFactor = under ? VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA : VK_BLEND_FACTOR_ONE,
         .dstAlphaBlendFactor = under ? VK_BLEND_FACTOR_ONE : VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
         .alphaBlendOp = VK_BLEND_OP_ADD,
         .colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                           VK_COLOR_COMPONENT_A_BIT});
    const VkPipelineColorBlendStateCreateInfo blend{.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
                                                    .attachmentCount = static_cast<uint32_t>(blends.size()),
                                                    .pAttachments = blends.data()};
    const VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                            VK_DYNAMIC_STATE_CULL_MODE, VK_DYNAMIC_STATE_FRONT_FACE};
    const VkPipelineDynamicStateCreateInfo dynamic{.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
                                                   .dynamicStateCount = desc.dynamicCullMode ? 4u : 2u,
                                                   .pDynamicStates = dynamicStates};
    const VkPipelineRenderingCreateInfo rendering{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                                  .colorAttachmentCount = static_cast<uint32_t>(desc.colorFormats.size()),
                                                  .pColorAttachmentFormats = desc.colorFormats.data(),
                                                  .depthAttachmentFormat = desc.depthFormat};
    const VkGraphicsPipelineCreateInfo info{.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                            .pNext = &rendering,
                                            .stageCount = static_cast<uint32_t>(stages.size()),
                                            .pStages = stages.data(),
                                            .pVertexInputState = &vertexInput,
                                            .pInputAssemblyState = &inputAssembly,
                                            .pViewportState = &viewport,
                                            .pRasterizationState = &raster,
                                            .pMultisampleState = &multisample,
                                            .pDepthStencilState = &depth,
                                            .pColorBlendState = &blend,
                                            .pDynamicState = &dynamic,
                                            .layout = out.mProgram.layout()};
    VkPipeline pipeline = VK_NULL_HANDLE;
    const auto start = std::chrono::steady_clock::now();
    VK_CHECK(vkCreateGraphicsPipelines(context.device(), context.pipelineCache(), 1, &info, nullptr, &pipeline));
    context.countPipelineCreation(uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start).count()));
    out.mPipeline = PipelineHandle(context, pipeline);
    return out;
}

std::string Pipeline::refresh(Context& context) {
    if (!mPipeline || !mProgram.stale()) return {};
    try {
        *this = mBindPoint == VK_PIPELINE_BIND_POINT_COMPUTE
                    ? compute(context, mShaderNames[0], mDesc.specialization)
                    : graphics(context, mShaderNames[0], mShaderNames[1], mDesc);
        return {};
    } catch (const std::exception& e) {
        // Keep the old pipeline; remember the new generations so the failure is not retried each frame.
        for (auto& source : mProgram.mSources) source.second = shader::shaderGeneration(source.first);
        log::error(std::string("rebuilding ") + mProgram.name() + ": " + e.what());
        return mProgram.name() + ": " + e.what();
    }
}

void Pipeline::bind(VkCommandBuffer cmd) const { vkCmdBindPipeline(cmd, mBindPoint, mPipeline.get()); }

void Pipeline::pushConstants(VkCommandBuffer cmd, const void* data, uint32_t size) const {
    const shader::PushConstantBlock& block = mProgram.reflection().pushConstants;
    if (size != block.size)
        throw InternalError(mProgram.name() + ": push constants of " + std::to_string(size) + " bytes, shader declares " +
                               std::to_string(block.size));
    vkCmdPushConstants(cmd, mProgram.layout(), block.stages, 0, size, data);
}

}  // namespace candela::vk
