#pragma once
// Helpers for the environment tests: a temporary folder, an independent Radiance RGBE writer (flat,
// new-style RLE and old-style RLE scanlines, any header) and EXR writers through OpenEXR's C++
// library (exr_test_writer.h), so every test builds its input files itself.

#include "assets/environment.h"
#include "test_paths.h"
#include "core/errors.h"

#include "exr_test_writer.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <unistd.h>

namespace candela::assets::test {

namespace fs = std::filesystem;
using Bytes = std::vector<uint8_t>;

// ../shared/assets/environments, or "" when that folder is absent.
inline fs::path sharedEnvironments() {
#ifdef CANDELA_SHARED_ASSETS
    const fs::path dir = ::candela::test::sharedAssets() / "environments";
    if (fs::is_directory(dir)) return dir;
#endif
    return {};
}

using EnvTempDir = candela::test::TempDir;

inline void writeBytes(const fs::path& path, const Bytes& bytes) {
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

inline Bytes toBytes(const std::string& text) { return Bytes(text.begin(), text.end()); }

// The error message loadEnvironment throws, or "" when it loads.
inline std::string environmentLoadError(const fs::path& path, const assets::EnvironmentLoadOptions& options = {}) {
    try {
        assets::loadEnvironment(path, options);
    } catch (const UserError& e) {
        return e.what();
    }
    return {};
}

// ---- RGBE ----------------------------------------------------------------------------------------

using Rgbe = std::array<uint8_t, 4>;

// Greg Ward's float → RGBE (truncating mantissas): every channel within max(r,g,b)/128 below the input.
inline Rgbe encodeRgbe(float r, float g, float b) {
    const float v = std::max({r, g, b});
    if (v < 1e-32f) return {0, 0, 0, 0};
    int e = 0;
    const float scale = std::frexp(v, &e) * 256.0f / v;
    return {uint8_t(r * scale), uint8_t(g * scale), uint8_t(b * scale), uint8_t(e + 128)};
}

// The exact value the reader must produce for an RGBE texel: m · 2^(e − 136), 0 when e = 0.
inline std::array<float, 3> decodeRgbe(const Rgbe& p) {
    if (p[3] == 0) return {0.0f, 0.0f, 0.0f};
    const float s = std::ldexp(1.0f, int(p[3]) - 136);
    return {p[0] * s, p[1] * s, p[2] * s};
}

enum class Scanlines { Flat, Rle, OldRle };

// A Radiance file written from RGBE texels (row-major, top row first, `width` per row).
struct HdrWriter {
    std::string magic = "#?RADIANCE\n";
    std::string headerLines = "FORMAT=32-bit_rle_rgbe\n";  // everything between the magic and the blank line
    std::string resolution;                                 // default "-Y H +X W"
    bool flipY = false;                                     // write rows bottom first (use with "+Y H +X W")
    bool flipX = false;                                     // write columns right to left ("-Y H -X W")
    Scanlines scanlines = Scanlines::Rle;

    Bytes write(const std::vector<Rgbe>& texels, uint32_t width, uint32_t height) const {
        Bytes out = toBytes(magic + headerLines + "\n" +
                            (resolution.empty() ? "-Y " + std::to_string(height) + " +X " + std::to_string(width)
                                                : resolution) +
                            "\n");
        for (uint32_t row = 0; row < height; ++row) {
            const uint32_t y = flipY ? height - 1 - row : row;
            std::vector<Rgbe> line(width);
            for (uint32_t col = 0; col < width; ++col) line[col] = texels[size_t(y) * width + (flipX ? width - 1 - col : col)];
            if (scanlines == Scanlines::Rle) appendRle(out, line);
            else if (scanlines == Scanlines::OldRle) appendOldRle(out, line);
            else
                for (const Rgbe& p : line) out.insert(out.end(), p.begin(), p.end());
        }
        return out;
    }

    // New-style: marker (2, 2, width >> 8, width & 255), then per channel runs of ≥ 3 equal bytes
    // as (128 + n, value) and everything else as literals (n ≤ 128, then n bytes).
    static void appendRle(Bytes& out, const std::vector<Rgbe>& line) {
        const size_t width = line.size();
        out.insert(out.end(), {2, 2, uint8_t(width >> 8), uint8_t(width & 255)});
        for (size_t c = 0; c < 4; ++c) {
            size_t x = 0;
            while (x < width) {
                size_t run = 1;
                while (x + run < width && run < 127 && line[x + run][c] == line[x][c]) ++run;
                if (run >= 3) {
                    out.push_back(uint8_t(128 + run));
                    out.push_back(line[x][c]);
                    x += run;
                    continue;
                }
                // A literal up to the next run of ≥ 3.
                size_t end = x;
                while (end < width && end - x < 128) {
                    if (end + 2 < width && line[end][c] == line[end + 1][c] && line[end][c] == line[end + 2][c]) break;
                    ++end;
                }
                if (end == x) end = x + 1;
                out.push_back(uint8_t(end - x));
                for (size_t i = x; i < end; ++i) out.push_back(line[i][c]);
                x = end;
            }
        }
    }

    // Old-style: a texel, then repeats as markers (1, 1, 1, n) with n's bytes least significant first.
    static void appendOldRle(Bytes& out, const std::vector<Rgbe>& line) {
        size_t x = 0;
        while (x < line.size()) {
            out.insert(out.end(), line[x].begin(), line[x].end());
            size_t repeat = 0;
            while (x + 1 + repeat < line.size() && line[x + 1 + repeat] == line[x]) ++repeat;
            for (size_t left = repeat; left > 0; left >>= 8) out.insert(out.end(), {1, 1, 1, uint8_t(left & 255)});
            x += 1 + repeat;
        }
    }
};

// A deterministic test image of `width` × `height` RGBE texels: gradients, zeros, runs of equal
// texels, a bright spot and very small values, so every code path of the encoders is exercised.
inline std::vector<Rgbe> testTexels(uint32_t width, uint32_t height) {
    std::vector<Rgbe> texels(size_t(width) * height);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            float r = 0.05f + 3.0f * float(x) / float(width), g = 0.5f + float(y), b = 0.25f * float((x * 7 + y * 3) % 11);
            if (x >= width / 2 && x < width / 2 + width / 4) r = 2.0f, g = 1.0f, b = 0.5f;  // a run
            if (x == 1 && y == 0) r = 50000.0f, g = 40000.0f, b = 30000.0f;                 // a sun
            if (x == 2) r = g = b = 0.0f;                                                   // black
            if (x == 3) r = 1e-6f, g = 2e-6f, b = 3e-7f;                                    // tiny
            texels[size_t(y) * width + x] = encodeRgbe(r, g, b);
        }
    }
    // No scanline may start like an RLE marker (2, 2, <128, ...) in the flat files.
    for (uint32_t y = 0; y < height; ++y) texels[size_t(y) * width] = encodeRgbe(0.7f, 0.6f, 0.5f);
    return texels;
}

// ---- EXR -----------------------------------------------------------------------------------------

using candela::test::ExrChannel;
using candela::test::ExrLayout;
using candela::test::ExrPart;
using candela::test::ExrType;
using candela::test::makeExr;
using candela::test::makeExrParts;
using candela::test::rgbChannels;

// Solid-angle-weighted mean luminance (Rec. 709 weights) of an equirectangular map.
inline double meanLuminance(const assets::Environment& env) {
    double sum = 0.0, weights = 0.0;
    for (uint32_t y = 0; y < env.height; ++y) {
        const double w = std::sin((y + 0.5) / env.height * 3.14159265358979);
        for (uint32_t x = 0; x < env.width; ++x) {
            const float* t = env.texel(x, y);
            sum += w * (0.2126 * t[0] + 0.7152 * t[1] + 0.0722 * t[2]);
            weights += w;
        }
    }
    return sum / weights;
}

}  // namespace candela::assets::test
