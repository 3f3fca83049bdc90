#include "assets/image_file.h"

#include "assets/output_file.h"
#include "assets/png_encoder.h"
#include "core/cache_files.h"
#include "core/errors.h"


#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace candela::assets {

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

namespace {

void checkSize(const std::filesystem::path& path, uint32_t width, uint32_t height, size_t have, size_t channels) {
    if (static_cast<size_t>(width) * height * channels != have)
        throw UserError(path.string() + ": internal error: pixel buffer size does not match " + std::to_string(width) +
                        "x" + std::to_string(height));
}

}  // namespace

ImageFileFormat imageFileFormat(const std::filesystem::path& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".png") return ImageFileFormat::Png;
    if (ext == ".exr") return ImageFileFormat::Exr;
    if (ext == ".pfm") return ImageFileFormat::Pfm;
    throw UserError(path.string() + ": unknown output format '" + (ext.empty() ? std::string("(none)") : ext) +
                    "' (use .png, .exr or .pfm)");
}

void checkWritable(const std::filesystem::path& path) {
    std::error_code ec;
    const bool existed = std::filesystem::exists(path, ec);
    if (existed && std::filesystem::is_directory(path, ec)) throw UserError(path.string() + ": is a directory");
    std::FILE* file = std::fopen(path.c_str(), "ab");
    if (!file) throw UserError(path.string() + ": cannot write: " + std::strerror(errno));
    std::fclose(file);
    if (!existed) std::filesystem::remove(path, ec);
}

void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const uint8_t> rgba) {
    checkSize(path, width, height, rgba.size(), 4);
    const std::vector<uint8_t> png = encodePng(width, height, rgba);
    writeFileAtomically(path, [&](std::ostream& out) { out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size())); });
}

void writeExr(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const float> rgba) {
    checkSize(path, width, height, rgba.size(), 4);
    writeOutputsExr(path, width, height, rgba, {});  // half RGBA and no other channel
}

void writePfm(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const float> rgba) {
    checkSize(path, width, height, rgba.size(), 4);
    writeFileAtomically(path, [&](std::ostream& out) {
        // Negative scale = little-endian; rows run bottom to top.
        out << "PF\n" << width << ' ' << height << "\n-1.0\n";
        std::vector<float> row(static_cast<size_t>(width) * 3);
        for (uint32_t y = height; y-- > 0;) {
            for (uint32_t x = 0; x < width; ++x)
                for (int c = 0; c < 3; ++c) row[x * 3 + c] = rgba[(static_cast<size_t>(y) * width + x) * 4 + c];
            out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size() * sizeof(float)));
        }
    });
}

namespace {

std::string readAll(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

bool pngComplete(const std::string& bytes) {
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char kEnd[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    return bytes.size() >= 8 + 12 && std::memcmp(bytes.data(), kSignature, 8) == 0 &&
           std::memcmp(bytes.data() + bytes.size() - 12, kEnd, 12) == 0 &&
           pngChunkProblem(std::span(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size())).empty();
}

bool pfmComplete(const std::string& bytes) {
    uint32_t width = 0, height = 0;
    double scale = 0.0;
    int consumed = 0;
    if (std::sscanf(bytes.c_str(), "PF\n%u %u\n%lf\n%n", &width, &height, &scale, &consumed) != 3 || consumed <= 0) return false;
    return bytes.size() == size_t(consumed) + size_t(width) * height * 3 * sizeof(float);
}

}  // namespace

bool imageFileComplete(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return false;
    try {
        if (lowerExtension(path) == ".npy") {
            const std::string bytes = readAll(path);
            return npyComplete(std::span(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()));
        }
        switch (imageFileFormat(path)) {
            case ImageFileFormat::Png: return pngComplete(readAll(path));
            case ImageFileFormat::Pfm: return pfmComplete(readAll(path));
            // Decoded whole, every channel (the outputs' too): OpenEXR's isComplete() checks the
            // offset table, not that the last chunk's data is all there.
            case ImageFileFormat::Exr: return exrDecodesWhole(path);
        }
    } catch (const std::exception&) {
    }
    return false;
}

size_t removeStaleTemporaries(const std::filesystem::path& path) {
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    const std::string prefix = path.filename().string() + ".tmp-";
    std::error_code ec;
    size_t removed = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.size() != prefix.size() + 16 || name.rfind(prefix, 0) != 0) continue;
        if (name.find_first_not_of("0123456789abcdef", prefix.size()) != std::string::npos) continue;
        removed += std::filesystem::remove(entry.path(), ec) ? 1 : 0;
    }
    return removed;
}

std::string pngChunkProblem(std::span<const uint8_t> bytes) {
    const auto be32 = [&](size_t at) {
        return uint32_t(bytes[at]) << 24 | uint32_t(bytes[at + 1]) << 16 | uint32_t(bytes[at + 2]) << 8 | bytes[at + 3];
    };
    for (size_t offset = 8; offset + 8 <= bytes.size();) {
        const uint64_t length = be32(offset);
        const std::string type(reinterpret_cast<const char*>(&bytes[offset + 4]), 4);
        if (length > bytes.size() - offset - 8)  // data (the CRC may be cut: stb_image ignores it)
            return "chunk " + type + " at byte " + std::to_string(offset) + " declares " + std::to_string(length) +
                   " bytes, past the end of the file (" + std::to_string(bytes.size()) + " bytes)";
        if (type == "IEND") break;
        offset += 12 + length;
    }
    return "";
}

}  // namespace candela::assets
