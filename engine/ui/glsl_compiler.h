#pragma once
// Run-time GLSL → SPIR-V compilation with the glslang library (the viewer's hot reload), with the
// same settings as the build (glslangValidator --target-env vulkan1.3 -g): Vulkan 1.3, SPIR-V 1.6,
// #include "..." resolved against the including file's folder and then `includeDir`, and the
// source text kept in the SPIR-V so the UI annotations survive.

#include <vulkan/vulkan_core.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace candela::ui {

struct CompileResult {
    std::vector<uint32_t> spirv;                  // empty on failure
    std::vector<std::string> errors;              // "FILE:LINE: message", one per diagnostic
    std::vector<std::filesystem::path> includes;  // headers read (for change tracking)
    bool ok() const { return !spirv.empty(); }
};

// Stage from a file name "NAME.STAGE.glsl" (vert, frag, comp); 0 if it has none of those.
VkShaderStageFlagBits stageOfFile(const std::filesystem::path& file);

// Compiles one shader file as `stage` with `defines` ("X" or "X=VALUE", as glslangValidator's -D,
// defined after the file's #version). Never throws for bad GLSL or unreadable files: they are errors.
CompileResult compileGlsl(const std::filesystem::path& file, const std::filesystem::path& includeDir,
                          VkShaderStageFlagBits stage, const std::vector<std::string_view>& defines);
// The same, as the stage the file's name gives (NAME.STAGE.glsl), without defines.
CompileResult compileGlsl(const std::filesystem::path& file, const std::filesystem::path& includeDir);

}  // namespace candela::ui
