#pragma once
// The images `candela diff` compares: 8-bit PNG (sRGB-encoded display values: LDR-ꟻLIP) and
// OpenEXR (linear radiance: HDR-ꟻLIP). Every failure is a UserError "PATH: problem", one line;
// nothing is read out of bounds and no absurd declared size is allocated.

#include "core/load_report.h"
#include "reports/flip.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace candela::reports {

enum class ComparedFormat { Png, Exr };

// The format a path's extension names (.png or .exr, any case); nullopt for anything else.
std::optional<ComparedFormat> comparedFormat(const std::filesystem::path& path);

// Images larger than this on a side, or with more pixels in all, are refused before their pixels
// are decoded (PNG) or compared (EXR).
inline constexpr uint32_t kMaxComparedSide = 16384;
inline constexpr uint64_t kMaxComparedPixels = uint64_t(8192) * 8192;

struct ComparedImage {
    ComparedFormat format = ComparedFormat::Png;
    uint32_t width = 0, height = 0;
    // PNG: the stored RGB values, 3 bytes a pixel (grey expanded, alpha dropped, 16-bit samples
    // rounded down to 8 bits as stb_image does). Empty for EXR.
    std::vector<uint8_t> rgb8;
    // Linear RGB: the PNG's values decoded with srgbToLinear; the EXR's R, G, B (or Y as grey; A
    // and other channels ignored) with NaN, ±∞ and negatives replaced as environments are
    // (assets::sanitizeEnvironment).
    RgbImage linear;
    LoadReport report;  // "PATH: ..." lines, e.g. the values replaced (warnings)
};

// Reads a PNG or EXR file, told apart by the extension (the content must match it).
ComparedImage readComparedImage(const std::filesystem::path& path);

}  // namespace candela::reports
