#include "shader/reflection.h"

#include <spirv_cross/spirv_cross_c.h>

#include <algorithm>
#include <map>
#include <memory>
#include <stdexcept>

namespace candela::shader {
namespace {

// Owns an spvc_context for the duration of one reflection.
struct SpvcContext {
    spvc_context handle = nullptr;
    SpvcContext() {
        if (spvc_context_create(&handle) != SPVC_SUCCESS) throw std::runtime_error("SPIRV-Cross: cannot create context");
    }
    ~SpvcContext() { spvc_context_destroy(handle); }
};

VkShaderStageFlagBits stageOf(SpvExecutionModel model) {
    switch (model) {
        case SpvExecutionModelVertex: return VK_SHADER_STAGE_VERTEX_BIT;
        case SpvExecutionModelFragment: return VK_SHADER_STAGE_FRAGMENT_BIT;
        case SpvExecutionModelGLCompute: return VK_SHADER_STAGE_COMPUTE_BIT;
        case SpvExecutionModelGeometry: return VK_SHADER_STAGE_GEOMETRY_BIT;
        case SpvExecutionModelTessellationControl: return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
        case SpvExecutionModelTessellationEvaluation: return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
        default: return VK_SHADER_STAGE_ALL;
    }
}

BaseType baseTypeOf(spvc_basetype type) {
    switch (type) {
        case SPVC_BASETYPE_FP32: return BaseType::Float;
        case SPVC_BASETYPE_INT32: return BaseType::Int;
        case SPVC_BASETYPE_UINT32: return BaseType::UInt;
        case SPVC_BASETYPE_BOOLEAN: return BaseType::Bool;
        case SPVC_BASETYPE_STRUCT: return BaseType::Struct;
        default: return BaseType::Other;
    }
}

using AnnotationMap = std::map<std::string, Annotation>;

void collectMembers(spvc_compiler compiler, spvc_type_id structId, const std::string& prefix, uint32_t baseOffset,
                    const AnnotationMap& annotations, std::vector<BlockMember>& out) {
    spvc_type type = spvc_compiler_get_type_handle(compiler, structId);
    const char* structName = spvc_compiler_get_name(compiler, structId);
    const std::string typeName = structName ? structName : "";
    const unsigned count = spvc_type_get_num_member_types(type);
    for (unsigned i = 0; i < count; ++i) {
        const spvc_type_id memberId = spvc_type_get_member_type(type, i);
        spvc_type member = spvc_compiler_get_type_handle(compiler, memberId);
        unsigned offset = 0;
        size_t size = 0;
        spvc_compiler_type_struct_member_offset(compiler, type, i, &offset);
        spvc_compiler_get_declared_struct_member_size(compiler, type, i, &size);
        const char* rawName = spvc_compiler_get_member_name(compiler, structId, i);
        const std::string name = prefix + (rawName && *rawName ? rawName : "_m" + std::to_string(i));
        const unsigned dims = spvc_type_get_num_array_dimensions(member);
        if (spvc_type_get_basetype(member) == SPVC_BASETYPE_STRUCT && dims == 0) {
            collectMembers(compiler, memberId, name + ".", baseOffset + offset, annotations, out);
            continue;
        }
        BlockMember m{.name = name,
                      .offset = baseOffset + offset,
                      .size = static_cast<uint32_t>(size),
                      .type = baseTypeOf(spvc_type_get_basetype(member)),
                      .vectorSize = spvc_type_get_vector_size(member),
                      .columns = spvc_type_get_columns(member),
                      .structName = typeName};
        if (const auto it = annotations.find(typeName + "." + (rawName ? rawName : "")); it != annotations.end())
            m.annotation = it->second;
        for (unsigned d = 0; d < dims; ++d) m.arraySize *= spvc_type_get_array_dimension(member, d);
        if (dims > 0) {
            unsigned stride = 0;
            spvc_compiler_type_struct_member_array_stride(compiler, type, i, &stride);
            m.arrayStride = stride;
            if (spvc_type_get_basetype(member) == SPVC_BASETYPE_STRUCT)
                collectMembers(compiler, spvc_type_get_base_type_id(member), "", 0, annotations, m.elementMembers);
        }
        out.push_back(std::move(m));
    }
}

}  // namespace

std::vector<std::string> embeddedSources(std::span<const uint32_t> spirv) {
    // Instruction stream after the 5-word header: (word count << 16 | opcode), operands.
    constexpr uint32_t kOpSourceContinued = 2, kOpSource = 3;
    std::vector<std::string> sources;
    const auto literal = [&](size_t first, size_t end) {
        std::string text;
        for (size_t w = first; w < end; ++w)
            for (int b = 0; b < 4; ++b) {
                const char c = static_cast<char>((spirv[w] >> (8 * b)) & 0xffu);
                if (c == '\0') return text;
                text += c;
            }
        return text;
    };
    for (size_t at = 5; at < spirv.size();) {
        const uint32_t count = spirv[at] >> 16, opcode = spirv[at] & 0xffffu;
        if (count == 0 || at + count > spirv.size()) break;  // malformed: stop, never read past the end
        if (opcode == kOpSource && count > 4) sources.push_back(literal(at + 4, at + count));  // language, version, file, text
        if (opcode == kOpSourceContinued && count > 1 && !sources.empty()) sources.back() += literal(at + 1, at + count);
        at += count;
    }
    return sources;
}

ShaderReflection reflectSpirv(std::span<const uint32_t> spirv, const std::string& debugName) {
    SpvcContext context;
    spvc_parsed_ir ir = nullptr;
    spvc_compiler compiler = nullptr;
    if (spirv.empty() ||
        spvc_context_parse_spirv(context.handle, reinterpret_cast<const SpvId*>(spirv.data()), spirv.size(), &ir) !=
            SPVC_SUCCESS ||
        spvc_context_create_compiler(context.handle, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler) !=
            SPVC_SUCCESS)
        throw std::runtime_error("cannot reflect shader " + debugName + ": " +
                                 spvc_context_get_last_error_string(context.handle));

    AnnotationMap annotations;
    for (const std::string& source : embeddedSources(spirv)) annotations.merge(parseAnnotations(source));

    ShaderReflection out;
    out.stage = stageOf(spvc_compiler_get_execution_model(compiler));
    spvc_resources resources = nullptr;
    spvc_compiler_create_shader_resources(compiler, &resources);

    const struct {
        spvc_resource_type spvc;
        VkDescriptorType vk;
    } kinds[] = {
        {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
        {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
        {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        {SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE},
        {SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, VK_DESCRIPTOR_TYPE_SAMPLER},
    };
    for (const auto& kind : kinds) {
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        spvc_resources_get_resource_list_for_type(resources, kind.spvc, &list, &count);
        for (size_t i = 0; i < count; ++i) {
            DescriptorBinding binding;
            const char* instance = spvc_compiler_get_name(compiler, list[i].id);
            binding.name = instance && *instance ? instance : list[i].name;
            binding.set = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
            binding.binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
            binding.type = kind.vk;
            binding.stages = out.stage;
            spvc_type type = spvc_compiler_get_type_handle(compiler, list[i].type_id);
            for (unsigned d = 0; d < spvc_type_get_num_array_dimensions(type); ++d)
                binding.count *= std::max(1u, spvc_type_get_array_dimension(type, d));
            if (kind.vk == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || kind.vk == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER)
                collectMembers(compiler, list[i].base_type_id, "", 0, annotations, binding.members);
            out.bindings.push_back(std::move(binding));
        }
    }
    std::sort(out.bindings.begin(), out.bindings.end(), [](const DescriptorBinding& a, const DescriptorBinding& b) {
        return a.set != b.set ? a.set < b.set : a.binding < b.binding;
    });

    const spvc_reflected_resource* push = nullptr;
    size_t pushCount = 0;
    spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_PUSH_CONSTANT, &push, &pushCount);
    if (pushCount > 0) {
        size_t size = 0;
        spvc_compiler_get_declared_struct_size(compiler, spvc_compiler_get_type_handle(compiler, push[0].base_type_id),
                                               &size);
        out.pushConstants.size = static_cast<uint32_t>(size);
        out.pushConstants.stages = out.stage;
        collectMembers(compiler, push[0].base_type_id, "", 0, annotations, out.pushConstants.members);
    }
    return out;
}

ShaderReflection mergeReflections(std::span<const ShaderReflection> stages) {
    ShaderReflection merged;
    merged.stage = static_cast<VkShaderStageFlagBits>(0);
    for (const ShaderReflection& stage : stages) {
        merged.stage = static_cast<VkShaderStageFlagBits>(merged.stage | stage.stage);
        for (const DescriptorBinding& binding : stage.bindings) {
            auto it = std::find_if(merged.bindings.begin(), merged.bindings.end(), [&](const DescriptorBinding& b) {
                return b.set == binding.set && b.binding == binding.binding;
            });
            if (it == merged.bindings.end()) {
                merged.bindings.push_back(binding);
            } else {
                if (it->type != binding.type || it->count != binding.count)
                    throw std::runtime_error("shader stages disagree on set " + std::to_string(binding.set) +
                                             " binding " + std::to_string(binding.binding) + " ('" + it->name +
                                             "' vs '" + binding.name + "')");
                it->stages |= binding.stages;
            }
        }
        if (stage.pushConstants.size > 0) {
            merged.pushConstants.stages |= stage.pushConstants.stages;
            if (stage.pushConstants.size > merged.pushConstants.size) {
                merged.pushConstants.size = stage.pushConstants.size;
                merged.pushConstants.members = stage.pushConstants.members;
            }
        }
    }
    std::sort(merged.bindings.begin(), merged.bindings.end(), [](const DescriptorBinding& a, const DescriptorBinding& b) {
        return a.set != b.set ? a.set < b.set : a.binding < b.binding;
    });
    return merged;
}

}  // namespace candela::shader
