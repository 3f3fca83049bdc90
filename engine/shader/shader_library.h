#pragma once
// The SPIR-V pipelines are built from: the built-in shaders (compiled at build time), or a
// replacement compiled at run time (the viewer's hot reload). Process-wide; main thread only.
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

// The current SPIR-V of shader "NAME.STAGE": its replacement if any, else the built-in one;
// empty if there is neither.
std::span<const uint32_t> shaderSpirv(std::string_view name);
// 0 for the built-in SPIR-V; incremented by every replacement.
uint64_t shaderGeneration(std::string_view name);
// Replaces the SPIR-V of a built-in shader. Precondition: the caller checked that it compiles and
// keeps the descriptor and push-constant layout (pipelines built before keep their sets).
void replaceShader(std::string_view name, std::vector<uint32_t> spirv);
// Back to the built-in SPIR-V everywhere (bumps the generations of the replaced shaders).
void restoreBuiltinShaders();

}  // namespace candela::shader
