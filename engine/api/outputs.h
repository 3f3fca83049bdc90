#pragma once
// Between the public API's per-pixel outputs (candela/image.h) and the engine's (options/
// pixel_output.h, render/readback.h), and writing them (engine/api/outputs.cpp).

#include "candela/image.h"
#include "options/pixel_output.h"
#include "render/readback.h"

#include <span>
#include <string>
#include <vector>

namespace candela {

// The engine's set of `outputs`.
options::PixelOutputs pixelOutputsOf(const std::vector<Output>& outputs);
// A capture's outputs besides colour as the API's images of width × height.
std::vector<OutputImage> outputImagesOf(const std::vector<CapturedOutput>& captured, uint32_t width, uint32_t height);
// Writes image.outputs where outputFiles(path, …, format) says: into the .exr at `path` with
// `rgba` (linear colour, or empty), else one file each. Throws UserError as the writers do.
void writeOutputFiles(const std::string& path, const Image& image, std::span<const float> rgba, OutputFileFormat format);

}  // namespace candela
