// candela::writeImage and bytesPerPixel (candela/image.h): the executable's image writers (the
// per-pixel outputs besides colour: engine/api/outputs.cpp).

#include "api/access.h"
#include "api/outputs.h"
#include "candela/image.h"
#include "assets/image_file.h"

#include <glm/gtc/packing.hpp>

#include <cstring>

namespace candela {

size_t bytesPerPixel(PixelFormat format) noexcept {
    switch (format) {
        case PixelFormat::Rgba8Srgb: return 4;
        case PixelFormat::Rgba16Float: return 8;
        case PixelFormat::Rgba32Float: return 16;
    }
    return 0;
}

void writeImage(const std::string& path, const Image& image, OutputFileFormat outputFormat) {
    translateErrors(path, [&] {
        const size_t values = size_t(image.width) * image.height * 4;
        const bool color = !image.pixels.empty();  // empty: colour was not rendered
        if (color && image.pixels.size() != values / 4 * bytesPerPixel(image.format))
            throw UserError(path + ": the image holds " + std::to_string(image.pixels.size()) + " bytes, not the " +
                            std::to_string(values / 4 * bytesPerPixel(image.format)) + " of its size and format");
        const assets::ImageFileFormat file = assets::imageFileFormat(path);
        if (file == assets::ImageFileFormat::Png && color) {
            if (image.format != PixelFormat::Rgba8Srgb)
                throw UserError(path + ": a PNG holds 8-bit sRGB pixels; render with PixelFormat::Rgba8Srgb, or write .exr or .pfm");
            assets::writePng(path, image.width, image.height,
                             std::span(reinterpret_cast<const uint8_t*>(image.pixels.data()), image.pixels.size()));
        }
        std::vector<float> rgba;
        if (file != assets::ImageFileFormat::Png && color) {
            if (image.format == PixelFormat::Rgba8Srgb)
                throw UserError(path + ": .exr and .pfm hold linear floats; render with PixelFormat::Rgba16Float or Rgba32Float");
            rgba.resize(values);
            if (image.format == PixelFormat::Rgba32Float) {
                std::memcpy(rgba.data(), image.pixels.data(), values * sizeof(float));
            } else {
                for (size_t i = 0; i < values; ++i) {
                    uint16_t half;
                    std::memcpy(&half, image.pixels.data() + i * 2, 2);
                    rgba[i] = glm::unpackHalf1x16(half);
                }
            }
        }
        if (file == assets::ImageFileFormat::Exr && (color || !image.outputs.empty())) {
            writeOutputFiles(path, image, rgba, outputFormat);
            return;
        }
        if (file == assets::ImageFileFormat::Pfm && color) assets::writePfm(path, image.width, image.height, rgba);
        if (!image.outputs.empty()) writeOutputFiles(path, image, {}, outputFormat);
    });
}

}  // namespace candela
