// The forward shader's structure (docs/shading.md): material evaluation and lighting are shared
// GLSL that a compute shader calls unchanged, and the ground truth of `ibl-report` is only in its
// own program.
#include "shader/builtin_shaders.h"
#include "temp_dir.h"
#include "ui/glsl_compiler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <span>
#include <vector>
#include <string>

namespace candela::test {
namespace {

// A compute shader that evaluates a material and lights it with the forward pass's own functions:
// only the stage's part — the inputs and how textures are read — is its own.
constexpr const char* kComputeBody = R"(
layout(local_size_x = 8) in;
#define CANDELA_CORE_TEXTURE(inputs, field, slot) textureLod(field##Texture, (inputs).uv[slot], 0.0f)
#define CANDELA_LAYER_TEXTURE(inputs, field, slot) textureLod(field##Texture, (inputs).layerUv[slot], 0.0f)
#include "shading/material_eval.glsl"
#include "shading/lighting.glsl"
layout(set = 4, binding = 0) writeonly buffer Radiance { vec4 radiance[]; };
void main() {
    SurfaceInputs inputs;
    inputs.draw = gl_GlobalInvocationID.x;
    inputs.eye = vec3(0.0f, 0.0f, 5.0f);
    inputs.position = vec3(0.0f);
    inputs.normal = vec3(0.0f, 0.0f, 1.0f);
    inputs.tangent = vec4(1.0f, 0.0f, 0.0f, 1.0f);
    inputs.faceNormal = vec3(0.0f, 0.0f, 1.0f);
    inputs.frontFacing = true;
    inputs.color = vec4(1.0f);
    inputs.normalChange = 0.0f;
    for (int i = 0; i < CANDELA_TEX_COUNT; ++i) inputs.uv[i] = vec2(0.5f);
#ifdef CANDELA_MATERIAL_LAYERS
    for (int i = 0; i < CANDELA_LAYER_TEX_COUNT; ++i) inputs.layerUv[i] = vec2(0.5f);
#endif
    Surface s = evaluateMaterial(inputs, materialBaseColor(inputs).rgb);
    SurfaceLight lit = plus(lightRadiance(s, lights[0]), imageBasedLight(s));
    radiance[gl_GlobalInvocationID.x] = vec4(lit.diffuse + lit.specular + lit.sheen + lit.coat, 1.0f);
}
)";

ui::CompileResult compileCompute(const TempDir& dir, const std::string& name, const std::string& defines) {
    const std::filesystem::path file = dir / (name + ".comp.glsl");
    std::ofstream(file) << "#version 460\n#extension GL_GOOGLE_include_directive : require\n" << defines << kComputeBody;
    return ui::compileGlsl(file, CANDELA_SHADER_SOURCE_DIR);
}

TEST(ForwardShader, MaterialEvaluationAndLightingCompileInAComputeShader) {
    const TempDir dir("candela_forward_shader");
    for (const auto& [name, defines] : {std::pair<std::string, std::string>{"core", ""},
                                        {"layered", "#define CANDELA_MATERIAL_LAYERS\n"}}) {
        const ui::CompileResult result = compileCompute(dir, name, defines);
        EXPECT_TRUE(result.ok()) << name << ": " << (result.errors.empty() ? "" : result.errors.front());
    }
}

// Whether built-in shader `program` compiled a function or variable whose debug name (OpName; the
// build keeps them) starts with `prefix` — what the program's code holds, not the text of its files.
bool compiles(const std::string& program, const std::string& prefix) {
    constexpr uint32_t kOpName = 5;
    const std::span<const uint32_t> words = shader::builtinShader(program);
    for (size_t i = 5; i < words.size();) {
        const uint32_t count = std::max(words[i] >> 16, 1u);
        if ((words[i] & 0xFFFFu) == kOpName && count > 2 && i + count <= words.size()) {
            const char* text = reinterpret_cast<const char*>(&words[i + 2]);
            const std::string name(text, strnlen(text, (count - 2) * sizeof(uint32_t)));
            if (name.starts_with(prefix)) return true;
        }
        i += count;
    }
    return false;
}

TEST(ForwardShader, GroundTruthOnlyInTheReportsProgram) {
    EXPECT_TRUE(compiles("forward_reference.frag", "referenceImageBasedLight("));
    EXPECT_TRUE(compiles("forward_reference.frag", "kReferenceSamples"));
    for (const char* production : {"forward.frag", "forward_layers.frag"}) {
        EXPECT_TRUE(compiles(production, "evaluateMaterial(")) << production;
        EXPECT_FALSE(compiles(production, "referenceImageBasedLight(")) << production;
        EXPECT_FALSE(compiles(production, "kReferenceSamples")) << production;
    }
}

// The opcodes of the SPIR-V instructions of `words` (after the 5-word header).
std::vector<uint32_t> opcodes(std::span<const uint32_t> words) {
    std::vector<uint32_t> out;
    for (size_t i = 5; i < words.size();) {
        const uint32_t count = words[i] >> 16;
        out.push_back(words[i] & 0xFFFFu);
        i += std::max(count, 1u);
    }
    return out;
}

// The alpha test demotes the fragment to a helper invocation instead of terminating it, so the
// derivatives and implicit-LOD samples its quad neighbours take after it stay defined.
TEST(ForwardShader, TheAlphaTestDemotesInsteadOfTerminating) {
    constexpr uint32_t kOpKill = 252, kOpTerminateInvocation = 4416, kOpDemoteToHelperInvocation = 5380;
    for (const char* program : {"forward.frag", "forward_layers.frag", "forward_reference.frag"}) {
        const std::vector<uint32_t> ops = opcodes(shader::builtinShader(program));
        ASSERT_FALSE(ops.empty()) << program;
        EXPECT_NE(std::find(ops.begin(), ops.end(), kOpDemoteToHelperInvocation), ops.end()) << program;
        EXPECT_EQ(std::find(ops.begin(), ops.end(), kOpKill), ops.end()) << program;
        EXPECT_EQ(std::find(ops.begin(), ops.end(), kOpTerminateInvocation), ops.end()) << program;
    }
}

}  // namespace
}  // namespace candela::test
