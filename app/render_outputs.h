#pragma once
// The files `candela render` writes for a scene: their names from --out and --outputs, the cameras'
// transforms file of a sequence, and whether --resume finds them complete.

#include "render_cli.h"

#include "candela/image.h"

#include <filesystem>
#include <string>
#include <vector>

namespace candela::app {

struct SceneInput;

// The API's outputs of --outputs.
std::vector<candela::Output> apiOutputs(const RenderOptions& options);
// The files one image at `path` is written as: the colour image and the other --outputs
// (candela::outputFiles).
std::vector<std::string> filesOf(const RenderOptions& options, const std::string& path);
// The files scene `input` writes for `variantName` ("default": the default materials): one, or
// one per frame of a sequence.
std::vector<std::string> outputsOf(const RenderOptions& options, const SceneInput& input, const std::string& variantName);
// The file of a sequence's cameras, in the folder of its first frame: transforms.json when that
// folder holds one sequence — the run has one scene or the --out pattern's folder has {name} or
// {path}, and one variant or {variant} in the folder — else NAME.transforms.json (NAME-VARIANT
// with --variant all), beside the other scenes' frames.
std::filesystem::path transformsFileOf(const RenderOptions& options, const SceneInput& input, const std::string& variantName,
                                       bool oneScene);
// --resume: whether every file scene `input` writes for `variantName` is there and a whole image,
// and for a sequence its transforms file a JSON document with a camera for each; removes what a
// killed writer left beside each (its temporary files) either way.
bool outputsComplete(const RenderOptions& options, const SceneInput& input, const std::string& variantName, bool oneScene);
// The name of `variant` in --out patterns: "default" for the default materials ("").
std::string variantNameOf(const std::string& variant);

}  // namespace candela::app
