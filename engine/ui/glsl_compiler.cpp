#include "ui/glsl_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>

namespace candela::ui {

namespace {

bool readText(const std::filesystem::path& path, std::string& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream text;
    text << in.rdbuf();
    out = text.str();
    return true;
}

// #include "name": the including file's folder first, then the shader root.
class Includer : public glslang::TShader::Includer {
public:
    explicit Includer(std::filesystem::path root) : mRoot(std::move(root)) {}
    IncludeResult* includeLocal(const char* header, const char* includer, size_t) override {
        for (const std::filesystem::path& dir : {std::filesystem::path(includer).parent_path(), mRoot}) {
            const std::filesystem::path path = dir / header;
            auto text = std::make_unique<std::string>();
            if (!readText(path, *text)) continue;
            includes.push_back(path);
            const std::string* data = text.release();
            return new IncludeResult(path.string(), data->data(), data->size(), const_cast<std::string*>(data));
        }
        return nullptr;  // glslang reports the failed include with file and line
    }
    IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
        return includeLocal(header, includer, depth);
    }
    void releaseInclude(IncludeResult* result) override {
        if (!result) return;
        delete static_cast<std::string*>(result->userData);
        delete result;
    }
    std::vector<std::filesystem::path> includes;

private:
    std::filesystem::path mRoot;
};

// glslang's log lines "ERROR: FILE:LINE: 'x' : message" → "FILE:LINE: 'x' : message".
void collectErrors(const char* log, std::vector<std::string>& out) {
    std::istringstream lines(log ? log : "");
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("ERROR: ", 0) != 0) continue;
        line = line.substr(7);
        if (line.find("compilation terminated") != std::string::npos || line.rfind("Linking", 0) == 0) continue;
        if (line.find(" compilation errors.") != std::string::npos) continue;
        out.push_back(line);
    }
}

EShLanguage languageOf(VkShaderStageFlagBits stage) {
    switch (stage) {
        case VK_SHADER_STAGE_VERTEX_BIT: return EShLangVertex;
        case VK_SHADER_STAGE_FRAGMENT_BIT: return EShLangFragment;
        default: return EShLangCompute;
    }
}

}  // namespace

VkShaderStageFlagBits stageOfFile(const std::filesystem::path& file) {
    const std::filesystem::path stem = file.extension() == ".glsl" ? file.stem() : file;
    const std::string stage = stem.extension().string();
    if (stage == ".vert") return VK_SHADER_STAGE_VERTEX_BIT;
    if (stage == ".frag") return VK_SHADER_STAGE_FRAGMENT_BIT;
    if (stage == ".comp") return VK_SHADER_STAGE_COMPUTE_BIT;
    return VkShaderStageFlagBits(0);
}

CompileResult compileGlsl(const std::filesystem::path& file, const std::filesystem::path& includeDir) {
    const VkShaderStageFlagBits stage = stageOfFile(file);
    if (stage == 0) {
        CompileResult result;
        result.errors.push_back(file.string() + ": not NAME.vert.glsl, NAME.frag.glsl or NAME.comp.glsl");
        return result;
    }
    return compileGlsl(file, includeDir, stage, {});
}

CompileResult compileGlsl(const std::filesystem::path& file, const std::filesystem::path& includeDir,
                          VkShaderStageFlagBits stage, const std::vector<std::string_view>& defines) {
    static std::once_flag initialized;
    std::call_once(initialized, [] { glslang::InitializeProcess(); });

    CompileResult result;
    std::string source;
    if (!readText(file, source)) {
        result.errors.push_back(file.string() + ": cannot read");
        return result;
    }
    const EShLanguage language = languageOf(stage);
    glslang::TShader shader(language);
    const char* text = source.c_str();
    const std::string name = file.string();
    const char* names[] = {name.c_str()};
    shader.setStringsWithLengthsAndNames(&text, nullptr, names, 1);
    // As glslangValidator -D: "#define X VALUE" lines read right after #version.
    std::string preamble;
    for (std::string_view define : defines) {
        const size_t equals = define.find('=');
        preamble += "#define " + std::string(define.substr(0, equals));
        if (equals != std::string_view::npos) preamble += " " + std::string(define.substr(equals + 1));
        preamble += "\n";
    }
    shader.setPreamble(preamble.c_str());
    shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_6);
    const EShMessages messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules | EShMsgDebugInfo);
    Includer includer(includeDir);
    if (!shader.parse(GetDefaultResources(), 460, false, messages, includer)) {
        collectErrors(shader.getInfoLog(), result.errors);
        if (result.errors.empty()) result.errors.push_back(name + ": " + shader.getInfoLog());
        result.includes = includer.includes;
        return result;
    }
    result.includes = includer.includes;
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) {
        collectErrors(program.getInfoLog(), result.errors);
        if (result.errors.empty()) result.errors.push_back(name + ": link: " + program.getInfoLog());
        return result;
    }
    glslang::SpvOptions options;
    options.generateDebugInfo = true;  // OpSource with the text: the annotations (as -g at build time)
    options.validate = true;
    glslang::GlslangToSpv(*program.getIntermediate(language), result.spirv, &options);
    return result;
}

}  // namespace candela::ui
