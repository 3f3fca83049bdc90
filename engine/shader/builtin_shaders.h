#pragma once
// SPIR-V of the shaders in shaders/, compiled at build time and embedded in the binary, so the
// executable needs no shader files at run time. Names are "NAME.STAGE", e.g. "encode.frag": the
// rows of shaders/builtin_shaders.txt.

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace candela::shader {

// The SPIR-V words of a built-in shader, or an empty span if there is none by that name.
std::span<const uint32_t> builtinShader(std::string_view name);
std::vector<std::string_view> builtinShaderNames();

// What built-in shader `name` is compiled from (its row of shaders/builtin_shaders.txt): the source
// file, relative to shaders/, and the defines, each "X" or "X=VALUE" as glslangValidator's -D takes
// them. An empty file if there is no built-in shader by that name. The strings are static.
struct BuiltinShaderSource {
    std::string_view file;
    std::vector<std::string_view> defines;
};
BuiltinShaderSource builtinShaderSource(std::string_view name);

}  // namespace candela::shader
