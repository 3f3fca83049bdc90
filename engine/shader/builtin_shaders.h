#pragma once
// SPIR-V of the shaders in shaders/, compiled at build time and embedded in the binary, so the
// executable needs no shader files at run time. Names are "NAME.STAGE", e.g. "encode.frag".

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace candela::shader {

// The SPIR-V words of a built-in shader, or an empty span if there is none by that name.
std::span<const uint32_t> builtinShader(std::string_view name);
std::vector<std::string_view> builtinShaderNames();

}  // namespace candela::shader
