#pragma once
// Writing captured frames to disk: PNG (8-bit, sRGB-encoded), OpenEXR (linear half float, through
// OpenEXR's C++ library: output_file.h's writer, without other channels) and PFM (linear 32-bit float RGB, written by hand: it is a 3-line header and raw floats).
// Every file is written to a temporary name in its folder and renamed into place
// (writeFileAtomically), so a run killed mid-write never leaves a truncated file under the final
// name. Every failure is a UserError naming the file and the problem.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace candela::assets {

enum class ImageFileFormat { Png, Exr, Pfm };

// The extension of `path`, lower-case (".png"; "" for none).
std::string lowerExtension(const std::filesystem::path& path);

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

// Whether the file at `path` is a whole image of its extension's format: a PNG whose chunks reach
// IEND, an EXR whose every channel decodes whole, a PFM as long as its header says, a NumPy .npy
// array (output_file.h) its data fills. False for a
// missing, truncated or foreign file. `candela render --resume` skips scenes whose outputs all are.
bool imageFileComplete(const std::filesystem::path& path);

// Removes what a killed writer of `path` left: the temporary files "<name>.tmp-<16 hex digits>"
// beside it (writeFileAtomically). Returns how many.
size_t removeStaleTemporaries(const std::filesystem::path& path);

// Reading PNG with stb_image: the first chunk whose declared length passes the end of `bytes`,
// as "chunk IDAT at byte 33 declares 1073741853 bytes, past the end of the file (120 bytes)"; ""
// when every chunk up to IEND (or to where the data ends) fits. stb_image grows its buffer to a
// chunk's declared length before reading it, so a file of a hundred bytes could make it allocate
// gigabytes: callers check this first. Precondition: `bytes` starts with the PNG signature.
std::string pngChunkProblem(std::span<const uint8_t> bytes);

}  // namespace candela::assets
