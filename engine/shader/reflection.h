#pragma once
// Reflection of SPIR-V (through SPIRV-Cross's C API): descriptor bindings, push-constant ranges and
// the members of uniform/push-constant blocks. Pipeline layouts are built from this, so no binding
// is written twice (once in GLSL, once in C++).

#include "shader/annotations.h"

#include <vulkan/vulkan_core.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace candela::shader {

enum class BaseType : uint8_t { Float, Int, UInt, Bool, Struct, Other };

// One member of a uniform or push-constant block (nested structs are flattened: "params.extent").
struct BlockMember {
    std::string name;
    uint32_t offset = 0;  // bytes from the start of the block
    uint32_t size = 0;    // declared size in bytes
    BaseType type = BaseType::Other;
    uint32_t vectorSize = 1;  // components per column
    uint32_t columns = 1;
    uint32_t arraySize = 1;   // 1 for non-arrays; 0 for a runtime-sized array
    std::string structName;   // the struct or block that declares the member ("TonemapParams")
    Annotation annotation;    // from the GLSL comments kept in the SPIR-V (see annotations.h)
    // Arrays of structs: the element's members (offsets from the element's start) and the stride.
    std::vector<BlockMember> elementMembers;
    uint32_t arrayStride = 0;
};

struct DescriptorBinding {
    std::string name;  // variable name (instance name for blocks if present, else block type name)
    uint32_t set = 0;
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
    uint32_t count = 1;
    VkShaderStageFlags stages = 0;
    std::vector<BlockMember> members;  // uniform/storage buffers
};

struct PushConstantBlock {
    uint32_t size = 0;  // bytes; 0 if the shader has none
    VkShaderStageFlags stages = 0;
    std::vector<BlockMember> members;
};

struct ShaderReflection {
    VkShaderStageFlagBits stage = VK_SHADER_STAGE_ALL;
    std::vector<DescriptorBinding> bindings;  // sorted by (set, binding)
    PushConstantBlock pushConstants;
};

// The GLSL source texts embedded in a SPIR-V module (OpSource/OpSourceContinued, present when it
// was compiled with debug information: glslangValidator -g), main file and included headers.
std::vector<std::string> embeddedSources(std::span<const uint32_t> spirv);

// Reflects one SPIR-V module; block members carry the annotations of its embedded sources. Throws std::runtime_error naming `debugName` if it cannot be parsed.
ShaderReflection reflectSpirv(std::span<const uint32_t> spirv, const std::string& debugName);

// Merges the reflection of the stages of one pipeline: bindings with the same (set, binding) are
// combined (stages OR'ed; a type or count mismatch throws), push-constant sizes take the maximum.
ShaderReflection mergeReflections(std::span<const ShaderReflection> stages);

}  // namespace candela::shader
