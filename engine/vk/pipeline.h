#pragma once
// Program: shader modules plus the descriptor-set layouts and pipeline layout derived from their
// SPIR-V reflection. Pipeline: a compute or graphics pipeline built from a Program (dynamic
// rendering, dynamic viewport and scissor), through the context's pipeline cache. Both move-only;
// destruction is deferred. Any thread may build them (a worker compiling ahead of the first draw:
// vk/pipeline_cache.h); using and refreshing one stays with the thread recording frames.

#include "shader/reflection.h"
#include "shader/specialize.h"
#include "vk/handle.h"

#include <string>
#include <string_view>
#include <vector>

namespace candela::vk {

// A program variant specialized at load (shader/specialize.h): `frozen` constants are fixed in the
// SPIR-V and what they leave unused removed; the layouts of `sets` then declare only the bindings
// the specialized code reads, the other sets every binding the shaders declare (so those sets stay
// compatible across the variants of a program).
struct ProgramSpecialization {
    std::vector<shader::FrozenConstant> frozen;
    std::vector<uint32_t> sets;
    // The fragment stage's output at location l moved to outputLocations[l] (shader::
    // remapOutputLocations); empty: as compiled.
    std::vector<uint32_t> outputLocations;
};

class Program {
public:
    friend class Pipeline;
    Program() = default;
    // Reflects the named shaders ("NAME.STAGE", their current SPIR-V: shader_library.h), specialized
    // as `specialization` says, and builds their layouts. Throws if a shader is missing or the stages
    // disagree on a binding; throws UserError if the layouts exceed the device's per-stage limits.
    Program(Context& context, const std::vector<std::string_view>& shaderNames,
            const ProgramSpecialization& specialization = {});

    // Whether set `set` declares a binding named `name`.
    bool declares(uint32_t set, std::string_view name) const;

    const shader::ShaderReflection& reflection() const { return mReflection; }
    VkPipelineLayout layout() const { return mLayout.get(); }
    // Layout of descriptor set `set` (an empty layout for sets the shaders do not use).
    VkDescriptorSetLayout setLayout(uint32_t set) const { return mSetLayouts.at(set).get(); }
    uint32_t setCount() const { return static_cast<uint32_t>(mSetLayouts.size()); }
    const std::string& name() const { return mName; }
    // Whether a shader was replaced (hot reload) since this program was built.
    bool stale() const;

    struct Stage {
        VkShaderStageFlagBits stage;
        ShaderModule module;
    };
    const std::vector<Stage>& stages() const { return mStages; }

private:
    std::string mName;
    std::vector<std::pair<std::string, uint64_t>> mSources;  // shader name, generation built from
    shader::ShaderReflection mReflection;
    std::vector<Stage> mStages;
    std::vector<DescriptorSetLayout> mSetLayouts;
    PipelineLayout mLayout;
};

enum class BlendMode : uint8_t {
    None,
    Premultiplied,  // colour = src + (1 − src.a)·dst, alpha likewise ("over")
    Under,          // colour = dst + (1 − dst.a)·src, alpha likewise (draws behind what is there)
};

struct GraphicsPipelineDesc {
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
    VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    bool depthTest = false;
    bool depthWrite = false;
    VkCompareOp depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL;  // reverse-Z
    BlendMode blend = BlendMode::None;
    uint32_t samples = 1;  // rasterization samples: the sample count of the attachments drawn into
    // Coverage from the fragment's alpha, and alpha 1 stored (alphaToOne). Precondition: samples > 1
    // and Context::alphaToOne().
    bool alphaToCoverage = false;
    // Cull mode and front face set per draw with vkCmdSetCullMode/FrontFace (Vulkan 1.3 core);
    // cullMode and frontFace above are then ignored.
    bool dynamicCullMode = false;
    // Specialization constant values, constant_id = index (32-bit each: bool as 0/1, uint, float bits).
    std::vector<uint32_t> specialization;
    // Constant ids fixed in the SPIR-V at load (values from `specialization`), and the descriptor
    // sets whose layouts then declare only what the specialized code reads (ProgramSpecialization).
    std::vector<uint32_t> frozenConstants;
    std::vector<uint32_t> specializedSets;
    // ProgramSpecialization::outputLocations: where the fragment stage's outputs go.
    std::vector<uint32_t> outputLocations;
    // Primitives are discarded before rasterization: a vertex-only program (fragment shader "").
    bool rasterizerDiscard = false;
    std::vector<VkVertexInputBindingDescription> vertexBindings;
    std::vector<VkVertexInputAttributeDescription> vertexAttributes;
};

// The specialization of the program Pipeline::graphics builds for `desc`: its frozen constants
// with their values, its specialized sets and output locations. A Program made with it has the
// layouts and reflection of that pipeline's, without compiling a pipeline.
ProgramSpecialization programSpecialization(const GraphicsPipelineDesc& desc);

class Pipeline {
public:
    Pipeline() = default;
    static Pipeline compute(Context& context, std::string_view shaderName,
                            const std::vector<uint32_t>& specialization = {});
    static Pipeline graphics(Context& context, std::string_view vertexShader, std::string_view fragmentShader,
                             const GraphicsPipelineDesc& desc);

    VkPipeline handle() const { return mPipeline.get(); }
    VkPipelineBindPoint bindPoint() const { return mBindPoint; }
    const Program& program() const { return mProgram; }
    VkPipelineLayout layout() const { return mProgram.layout(); }

    // Rebuilds the pipeline from the current SPIR-V of its shaders if one was replaced since it was
    // built (hot reload). The old pipeline is dropped through the deferred deletion queue, so frames
    // in flight may still use it. If the rebuild fails, the old pipeline stays and the error is
    // returned (and not retried until the shader changes again); "" otherwise.
    std::string refresh(Context& context);

    // Binds the pipeline on `cmd`.
    void bind(VkCommandBuffer cmd) const;
    // Pushes `size` bytes of constants to every stage that declares the block.
    // Precondition: size equals the reflected push-constant block size.
    void pushConstants(VkCommandBuffer cmd, const void* data, uint32_t size) const;

private:
    Program mProgram;
    PipelineHandle mPipeline;
    VkPipelineBindPoint mBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    // How it was made, for refresh().
    std::vector<std::string> mShaderNames;
    GraphicsPipelineDesc mDesc;  // graphics; compute uses its specialization only
};

}  // namespace candela::vk
