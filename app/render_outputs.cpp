// The files `candela render` writes for a scene (render_outputs.h says what each function does).

#include "render_outputs.h"

#include "scene_batch.h"
#include "assets/image_file.h"
#include "candela/dataset.h"

#include <fstream>

#include <nlohmann/json.hpp>

namespace candela::app {

namespace fs = std::filesystem;

std::vector<candela::Output> apiOutputs(const RenderOptions& options) {
    std::vector<candela::Output> out;
    for (candela::Output o : candela::allOutputs())
        if (options.outputs.has(options::PixelOutput(uint32_t(o)))) out.push_back(o);
    return out;
}

std::vector<std::string> filesOf(const RenderOptions& options, const std::string& path) {
    return candela::outputFiles(path, apiOutputs(options), candela::OutputFileFormat(uint32_t(options.outputsFormat)));
}

std::vector<std::string> outputsOf(const RenderOptions& options, const SceneInput& input, const std::string& variantName) {
    if (!options.sequence()) return {expandOutPattern(options.out, {input.name, input.path, variantName, std::nullopt})};
    std::vector<std::string> out;
    for (uint32_t i = 0; i < options.frameCount(); ++i)
        out.push_back(expandOutPattern(options.out, {input.name, input.path, variantName, i}));
    return out;
}

fs::path transformsFileOf(const RenderOptions& options, const SceneInput& input, const std::string& variantName,
                          bool oneScene) {
    const std::string folderPattern = fs::path(options.out).parent_path().string();
    const bool sceneFolder = oneScene || folderPattern.find("{name}") != std::string::npos ||
                             folderPattern.find("{path}") != std::string::npos;
    const bool variantFolder = options.variant != "all" || folderPattern.find("{variant}") != std::string::npos;
    const fs::path folder = fs::path(expandOutPattern(options.out, {input.name, input.path, variantName, 0u})).parent_path();
    if (sceneFolder && variantFolder) return folder / "transforms.json";
    return folder / (input.name + (options.variant == "all" ? "-" + variantName : "") + ".transforms.json");
}

bool outputsComplete(const RenderOptions& options, const SceneInput& input, const std::string& variantName, bool oneScene) {
    const std::vector<std::string> outputs = outputsOf(options, input, variantName);
    bool complete = true;
    for (const std::string& out : outputs)
        for (const std::string& file : filesOf(options, out)) {
            assets::removeStaleTemporaries(file);
            complete = complete && assets::imageFileComplete(file);
        }
    if (options.sequence()) {
        const fs::path transforms = transformsFileOf(options, input, variantName, oneScene);
        assets::removeStaleTemporaries(transforms);
        std::ifstream in(transforms);
        const nlohmann::json json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
        complete = complete && json.is_object() && json.contains("frames") && json["frames"].size() == outputs.size();
    }
    return complete;
}

std::string variantNameOf(const std::string& variant) { return variant.empty() ? "default" : variant; }

}  // namespace candela::app
