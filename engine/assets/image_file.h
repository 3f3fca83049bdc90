#pragma once
// Writing captured frames to disk: PNG (8-bit, sRGB-encoded), OpenEXR (linear half float, through
// OpenEXR's C++ library) and PFM (linear 32-bit float RGB, written by hand: it is a 3-line header and raw floats).
// Every failure is a UserError naming the file and the problem.

#include <cstdint>
#include <filesystem>
#include <span>

namespace candela::io {

enum class ImageFileFormat { Png, Exr, Pfm };

// The format implied by the path's extension (.png, .exr, .pfm; case-insensitive).
// Throws UserError naming the file for any other extension.
ImageFileFormat imageFileFormat(const std::filesystem::path& path);

// True for formats that store linear float radiance (EXR, PFM).
inline bool isFloatFormat(ImageFileFormat format) { return format != ImageFileFormat::Png; }

// Checks that `path` can be created or overwritten, before any rendering work is done.
// A file that did not exist before is removed again. Throws UserError naming the file.
void checkWritable(const std::filesystem::path& path);

// `rgba`: width × height × 4 bytes, top row first.
void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const uint8_t> rgba);
// `rgba`: width × height × 4 floats, top row first. Alpha is written to EXR, dropped for PFM.
void writeExr(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const float> rgba);
void writePfm(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const float> rgba);

}  // namespace candela::io
