#pragma once
// The SPIR-V pipelines are built from: the built-in shaders (compiled at build time), or a
// replacement compiled at run time (the viewer's hot reload). Process-wide. Any thread may read
// (pipelines are built on worker threads too); replacements come from one thread at a time.
//
// Each replacement bumps the shader's generation; a vk::Program remembers the generations it was
// built from, so pipelines notice that they are stale and are rebuilt at their next use
// (vk::Pipeline::refresh).

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace candela::shader {

// A shader's SPIR-V with the generation it belongs to.
struct ShaderVersion {
    std::span<const uint32_t> spirv;  // valid until the process exits (replaced code is kept)
    uint64_t generation = 0;
};

// The current SPIR-V of shader "NAME.STAGE" and its generation, read together: its replacement
// if any, else the built-in one; empty SPIR-V if there is neither.
ShaderVersion currentShader(std::string_view name);
// currentShader(name).spirv.
std::span<const uint32_t> shaderSpirv(std::string_view name);
// 0 for the built-in SPIR-V; incremented by every replacement.
uint64_t shaderGeneration(std::string_view name);
// Replaces the SPIR-V of a built-in shader. Precondition: the caller checked that it compiles and
// keeps the descriptor and push-constant layout (pipelines built before keep their sets). The
// previous replacement's SPIR-V stays in memory (a pipeline may be reading it on another thread).
void replaceShader(std::string_view name, std::vector<uint32_t> spirv);
// Back to the built-in SPIR-V everywhere (bumps the generations of the replaced shaders).
void restoreBuiltinShaders();

}  // namespace candela::shader
