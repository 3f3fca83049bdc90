// The per-pixel outputs in the public API (candela/image.h): their names and channels (from
// options/pixel_output.h, the one table), the files writeImage puts them in, and the pictures of
// them a .png holds.

#include "api/access.h"
#include "api/outputs.h"
#include "assets/image_file.h"
#include "assets/output_file.h"
#include "candela/image.h"
#include "options/pixel_output.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace candela {

namespace {

options::PixelOutput pixelOutputOf(Output output) { return options::PixelOutput(uint32_t(output)); }
static_assert(uint32_t(Output::InstanceId) + 1 == options::kPixelOutputCount, "Output and options::PixelOutput differ");

std::string extensionOf(OutputFileFormat format) {
    switch (format) {
        case OutputFileFormat::Npy: return ".npy";
        case OutputFileFormat::Exr: return ".exr";
        case OutputFileFormat::Png: return ".png";
    }
    return ".npy";
}

uint8_t unorm8(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }
uint8_t srgb8(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return unorm8(v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f);
}

// An 8-bit picture of `image` to look at: depth as grey, near bright (over the image's range of
// finite depths); normals as n · ½ + ½; colours sRGB-encoded; metallic and roughness in red and
// green; each ID its own colour; nothing drawn black.
std::vector<uint8_t> pictureOf(const OutputImage& image) {
    const size_t pixels = size_t(image.width) * image.height;
    std::vector<uint8_t> rgba(pixels * 4, 0);
    float nearest = std::numeric_limits<float>::infinity(), farthest = 0.0f;
    if (image.output == Output::Depth)
        for (float d : image.values)
            if (std::isfinite(d)) nearest = std::min(nearest, d), farthest = std::max(farthest, d);
    for (size_t i = 0; i < pixels; ++i) {
        uint8_t* out = &rgba[i * 4];
        out[3] = 255;
        if (!image.ids.empty()) {
            const uint32_t id = image.ids[i];
            if (id == NoId) continue;
            uint32_t h = id * 2654435761u;  // Knuth's multiplicative hash: neighbours far apart
            h ^= h >> 15;
            for (int c = 0; c < 3; ++c) out[c] = uint8_t(64 + ((h >> (8 * c)) & 0xFF) % 192);
            continue;
        }
        const float* v = &image.values[i * image.channels];
        switch (image.output) {
            case Output::Depth: {
                if (!std::isfinite(v[0])) break;
                const float t = farthest > nearest ? (farthest - v[0]) / (farthest - nearest) : 1.0f;
                out[0] = out[1] = out[2] = unorm8(0.15f + 0.85f * t);
                break;
            }
            case Output::Normal:
                if (v[0] != 0.0f || v[1] != 0.0f || v[2] != 0.0f)
                    for (int c = 0; c < 3; ++c) out[c] = unorm8(v[c] * 0.5f + 0.5f);
                break;
            case Output::BaseColor:
            case Output::Emissive:
                for (int c = 0; c < 3; ++c) out[c] = srgb8(v[c]);
                break;
            case Output::MetallicRoughness:
                out[0] = unorm8(v[0]);
                out[1] = unorm8(v[1]);
                break;
            default:  // one channel: clip depth, alpha
                out[0] = out[1] = out[2] = unorm8(v[0]);
        }
    }
    return rgba;
}

// The named plane of `image` for the writers (EXR channel names "OUTPUT.CHANNEL"; depth's is Z).
assets::OutputPlane planeOf(const OutputImage& image) {
    assets::OutputPlane plane{.name = outputName(image.output), .integer = !image.ids.empty(), .floats = image.values, .ids = image.ids};
    for (const std::string& channel : outputChannels(image.output))
        plane.channels.push_back(image.output == Output::Depth ? channel : plane.name + "." + channel);
    return plane;
}

}  // namespace

const char* outputName(Output output) noexcept { return options::pixelOutputName(pixelOutputOf(output)); }

std::vector<Output> allOutputs() {
    std::vector<Output> out;
    for (const auto& [o, name] : options::kPixelOutputNames) out.push_back(Output(uint32_t(o)));
    return out;
}

std::vector<Output> outputsNamed(std::string_view name) {
    const std::string_view names[] = {name};
    std::vector<Output> out;
    if (const std::optional<options::PixelOutputs> set = options::pixelOutputsNamed(names))
        for (Output o : allOutputs())
            if (set->has(pixelOutputOf(o))) out.push_back(o);
    return out;
}

std::vector<std::string> outputChannels(Output output) {
    const options::PixelOutputLayout layout = options::pixelOutputLayout(pixelOutputOf(output));
    return {layout.channelNames.begin(), layout.channelNames.begin() + layout.channels};
}

options::PixelOutputs pixelOutputsOf(const std::vector<Output>& outputs) {
    options::PixelOutputs set;
    for (Output o : outputs) set.add(pixelOutputOf(o));
    return set;
}

std::vector<OutputImage> outputImagesOf(const std::vector<CapturedOutput>& captured, uint32_t width, uint32_t height) {
    std::vector<OutputImage> out;
    for (const CapturedOutput& c : captured)
        out.push_back({.output = Output(uint32_t(c.output)), .width = width, .height = height, .channels = c.channels,
                       .values = c.floats, .ids = c.ids});
    return out;
}

std::vector<std::string> outputFiles(const std::string& path, const std::vector<Output>& outputs, OutputFileFormat format) {
    std::vector<std::string> files;
    translateErrors(path, [&] {
        const assets::ImageFileFormat file = assets::imageFileFormat(path);
        const bool color = std::find(outputs.begin(), outputs.end(), Output::Color) != outputs.end();
        const bool others = std::any_of(outputs.begin(), outputs.end(), [](Output o) { return o != Output::Color; });
        if (file == assets::ImageFileFormat::Exr) {
            if (color || others) files.push_back(path);
            return;
        }
        if (color) files.push_back(path);
        const std::filesystem::path p(path);
        for (Output o : allOutputs())
            if (o != Output::Color && std::find(outputs.begin(), outputs.end(), o) != outputs.end())
                files.push_back((p.parent_path() / (p.stem().string() + "." + outputName(o) + extensionOf(format))).string());
    });
    return files;
}

void writeOutputFiles(const std::string& path, const Image& image, std::span<const float> rgba, OutputFileFormat format) {
    std::vector<assets::OutputPlane> planes;
    for (const OutputImage& o : image.outputs) planes.push_back(planeOf(o));
    if (assets::imageFileFormat(path) == assets::ImageFileFormat::Exr) {
        assets::writeOutputsExr(path, image.width, image.height, rgba, planes);
        return;
    }
    std::vector<Output> outputs;
    for (const OutputImage& o : image.outputs) outputs.push_back(o.output);
    const std::vector<std::string> files = outputFiles(path, outputs, format);
    const size_t first = files.size() - image.outputs.size();  // after the colour image's, if any
    for (size_t i = 0; i < image.outputs.size(); ++i) {
        const std::string& file = files[first + i];
        switch (format) {
            case OutputFileFormat::Npy: assets::writeNpy(file, image.width, image.height, planes[i]); break;
            case OutputFileFormat::Exr: assets::writeOutputsExr(file, image.width, image.height, {}, std::span(&planes[i], 1)); break;
            case OutputFileFormat::Png: assets::writePng(file, image.width, image.height, pictureOf(image.outputs[i])); break;
        }
    }
}

}  // namespace candela
