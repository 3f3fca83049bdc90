#include "assets/image_file.h"

#include "core/errors.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <stb_image_write.h>

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
    if (!stbi_write_png(path.c_str(), static_cast<int>(width), static_cast<int>(height), 4, rgba.data(),
                        static_cast<int>(width * 4)))
        throw UserError(path.string() + ": cannot write PNG");
}

void writeExr(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const float> rgba) {
    checkSize(path, width, height, rgba.size(), 4);
    // Half RGBA, ZIP (lossless; 16 scanlines per chunk), through OpenEXR's C++ library. It writes
    // only from slices of the channels' own type, so the floats are rounded to half here.
    Imf::Header header(static_cast<int>(width), static_cast<int>(height));
    header.compression() = Imf::ZIP_COMPRESSION;
    std::vector<Imath::half> halves(rgba.begin(), rgba.end());
    Imf::FrameBuffer frame;
    const char* names[] = {"R", "G", "B", "A"};
    char* base = reinterpret_cast<char*>(halves.data());
    for (size_t c = 0; c < 4; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::HALF));
        frame.insert(names[c], Imf::Slice(Imf::HALF, base + c * sizeof(Imath::half), 4 * sizeof(Imath::half),
                                          size_t(width) * 4 * sizeof(Imath::half)));
    }
    try {
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(static_cast<int>(height));
    } catch (const std::exception& e) {
        std::string message = e.what();
        std::replace(message.begin(), message.end(), '\n', ' ');
        throw UserError(path.string() + ": cannot write EXR: " + message);
    }
}

void writePfm(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const float> rgba) {
    checkSize(path, width, height, rgba.size(), 4);
    std::ofstream out(path, std::ios::binary);
    if (!out) throw UserError(path.string() + ": cannot write: " + std::strerror(errno));
    // Negative scale = little-endian; rows run bottom to top.
    out << "PF\n" << width << ' ' << height << "\n-1.0\n";
    std::vector<float> row(static_cast<size_t>(width) * 3);
    for (uint32_t y = height; y-- > 0;) {
        for (uint32_t x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) row[x * 3 + c] = rgba[(static_cast<size_t>(y) * width + x) * 4 + c];
        out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size() * sizeof(float)));
    }
    if (!out) throw UserError(path.string() + ": write failed");
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
