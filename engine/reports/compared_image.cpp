#include "reports/compared_image.h"

#include "assets/environment.h"
#include "assets/image_file.h"
#include "core/errors.h"

#include <stb_image.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>

namespace candela::reports {
namespace {

struct StbiFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& problem) {
    throw UserError(path.string() + ": " + problem);
}

std::vector<uint8_t> readBytes(const std::filesystem::path& path, size_t limit) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, std::string("cannot open: ") + std::strerror(errno));
    std::vector<uint8_t> bytes;
    std::array<char, 65536> chunk;
    while (in.read(chunk.data(), chunk.size()) || in.gcount() > 0) {
        bytes.insert(bytes.end(), chunk.data(), chunk.data() + in.gcount());
        if (bytes.size() >= limit) break;
    }
    if (in.bad()) fail(path, "read failed");
    return bytes;
}

void checkSize(const std::filesystem::path& path, uint64_t width, uint64_t height) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width == 0 || height == 0) fail(path, "zero image size " + size);
    if (width > kMaxComparedSide || height > kMaxComparedSide || width * height > kMaxComparedPixels)
        fail(path, "image size " + size + " exceeds the limit (" + std::to_string(kMaxComparedSide) + " a side, " +
                       std::to_string(kMaxComparedPixels) + " pixels)");
}

ComparedImage readPng(const std::filesystem::path& path) {
    const std::vector<uint8_t> bytes = readBytes(path, SIZE_MAX);
    constexpr uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < 8 || !std::equal(kSignature, kSignature + 8, bytes.begin())) fail(path, "not a PNG file");
    if (bytes.size() > size_t(INT32_MAX)) fail(path, "file too large");
    const int length = int(bytes.size());
    // The size the header declares, checked before stb_image allocates anything.
    if (bytes.size() < 24) fail(path, "truncated PNG (" + std::to_string(bytes.size()) + " bytes)");
    if (!std::equal(bytes.begin() + 12, bytes.begin() + 16, "IHDR")) fail(path, "not a PNG file (no IHDR chunk first)");
    const auto be32 = [&](size_t at) { return uint32_t(bytes[at]) << 24 | uint32_t(bytes[at + 1]) << 16 | uint32_t(bytes[at + 2]) << 8 | bytes[at + 3]; };
    checkSize(path, be32(16), be32(20));
    if (const std::string problem = assets::pngChunkProblem(bytes); !problem.empty()) fail(path, problem);
    int w = 0, h = 0, channels = 0;
    std::unique_ptr<uint8_t, StbiFree> pixels(stbi_load_from_memory(bytes.data(), length, &w, &h, &channels, 3));
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        fail(path, std::string("cannot decode PNG") + (reason ? std::string(" (") + reason + ")" : ""));
    }
    checkSize(path, uint64_t(w), uint64_t(h));
    ComparedImage image{ComparedFormat::Png, uint32_t(w), uint32_t(h), {}, {}, {}};
    image.rgb8.assign(pixels.get(), pixels.get() + size_t(w) * h * 3);
    float decode[256];
    for (int v = 0; v < 256; ++v) decode[v] = srgbToLinear(uint8_t(v));
    image.linear = {image.width, image.height, std::vector<float>(image.rgb8.size())};
    for (size_t i = 0; i < image.rgb8.size(); ++i) image.linear.rgb[i] = decode[image.rgb8[i]];
    return image;
}

ComparedImage readExr(const std::filesystem::path& path) {
    const std::vector<uint8_t> magic = readBytes(path, 4);
    if (magic.size() < 4 || magic[0] != 0x76 || magic[1] != 0x2f || magic[2] != 0x31 || magic[3] != 0x01)
        fail(path, "not an OpenEXR file");
    assets::Environment exr = assets::loadEnvironment(path, {.maxWidth = kMaxComparedSide, .maxHeight = kMaxComparedSide});
    checkSize(path, exr.width, exr.height);
    ComparedImage image{ComparedFormat::Exr, exr.width, exr.height, {}, {exr.width, exr.height, std::move(exr.rgb)}, {}};
    // The environment reader's warnings are about environments (an aspect other than 2:1); only
    // the values it replaced matter here.
    if (exr.replacedTexels)
        image.report.warnings.push_back(path.string() + ": " + std::to_string(exr.replacedTexels) +
                                 " pixels held NaN, infinite or negative values, compared as 0 (+infinity as the "
                                 "largest finite value, at least 65504)");
    return image;
}

}  // namespace

std::optional<ComparedFormat> comparedFormat(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".png") return ComparedFormat::Png;
    if (ext == ".exr") return ComparedFormat::Exr;
    return std::nullopt;
}

ComparedImage readComparedImage(const std::filesystem::path& path) {
    const std::optional<ComparedFormat> format = comparedFormat(path);
    if (!format) fail(path, "not a .png or .exr file");
    return *format == ComparedFormat::Png ? readPng(path) : readExr(path);
}

}  // namespace candela::reports
