#include "assets/environment.h"

#include "assets/exr_reader.h"
#include "assets/hdr_reader.h"
#include "assets/image_file.h"
#include "core/cache_files.h"
#include "core/errors.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <limits>

namespace candela::assets {
namespace {

constexpr float kHalfMax = 65504.0f;

std::vector<uint8_t> readFile(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw UserError(name + ": is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw UserError(name + ": cannot open: " + std::strerror(errno));
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) throw UserError(name + ": cannot read");
    if (size == 0) throw UserError(name + ": empty file");
    in.seekg(0, std::ios::beg);
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    if (!in.read(reinterpret_cast<char*>(bytes.data()), size)) throw UserError(name + ": read failed");
    return bytes;
}

}  // namespace

void checkEnvironmentSize(const std::string& source, uint64_t width, uint64_t height,
                          const EnvironmentLoadOptions& options) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width == 0 || height == 0) throw UserError(source + ": zero image size " + size);
    if (width > options.maxWidth || height > options.maxHeight)
        throw UserError(source + ": image size " + size + " exceeds the limit " + std::to_string(options.maxWidth) +
                        "x" + std::to_string(options.maxHeight));
}

Environment loadEnvironment(const std::filesystem::path& path, const EnvironmentLoadOptions& options) {
    return decodeEnvironment(readFile(path), path.string(), options);
}

Environment decodeEnvironment(std::span<const uint8_t> bytes, const std::string& source, const EnvironmentLoadOptions& options) {
    Environment env;
    if (looksLikeHdr(bytes)) {
        env = decodeHdr(bytes, source, options);
    } else if (looksLikeExr(bytes)) {
        env = decodeExr(bytes, source, options);
    } else {
        // Neither magic: let the extension's decoder name the problem.
        const std::string ext = lowerExtension(source);
        if (ext == ".hdr" || ext == ".pic" || ext == ".rgbe") decodeHdr(bytes, source, options);
        if (ext == ".exr") decodeExr(bytes, source, options);
        throw UserError(source + ": unknown environment format (expected a Radiance .hdr or an OpenEXR .exr file)");
    }
    if (env.width != 2 * env.height)
        env.report.warnings.push_back(source + ": " + std::to_string(env.width) + "x" + std::to_string(env.height) +
                               " is not 2:1; it is mapped as equirectangular anyway");
    sanitizeEnvironment(env);
    return env;
}

uint32_t sanitizeEnvironment(Environment& env) {
    // +Inf becomes the brightest finite value, so an overflowed sun stays the brightest texel.
    float brightest = kHalfMax;
    for (float v : env.rgb)
        if (std::isfinite(v)) brightest = std::max(brightest, v);

    uint32_t texels = 0, nans = 0, infinities = 0, negatives = 0;
    const size_t count = env.rgb.size() / 3;
    for (size_t i = 0; i < count; ++i) {
        bool replaced = false;
        for (size_t c = 0; c < 3; ++c) {
            float& v = env.rgb[i * 3 + c];
            if (std::isnan(v)) {
                v = 0.0f, replaced = true, ++nans;
            } else if (v == std::numeric_limits<float>::infinity()) {
                v = brightest, replaced = true, ++infinities;
            } else if (v < 0.0f) {
                v = 0.0f, replaced = true, ++negatives;
            } else if (v == 0.0f) {
                v = 0.0f;  // −0 → +0
            }
        }
        texels += replaced ? 1 : 0;
    }
    if (texels > 0) {
        char brightestText[32];
        std::snprintf(brightestText, sizeof brightestText, "%g", double(brightest));
        env.report.warnings.push_back(env.source + ": replaced " + std::to_string(texels) + " texel" +
                               (texels == 1 ? "" : "s") + " holding NaN, Inf or negative values (" +
                               std::to_string(nans) + " NaN and " + std::to_string(negatives) +
                               " negative values set to 0, " + std::to_string(infinities) + " +Inf set to " +
                               brightestText + ")");
    }
    env.replacedTexels += texels;
    return texels;
}

uint64_t contentHash(const Environment& env) {
    WordHasher hasher;
    // 32-bit values (unsigned or float) as little-endian words.
    const auto words = [&hasher](const void* values, size_t count) {
        if constexpr (std::endian::native == std::endian::little) {
            hasher.update(values, count * 4);
        } else {
            for (size_t i = 0; i < count; ++i) {
                uint32_t v;
                std::memcpy(&v, static_cast<const std::byte*>(values) + 4 * i, 4);
                const std::array<uint8_t, 4> le = {uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)};
                hasher.update(le.data(), le.size());
            }
        }
    };
    const std::array<uint32_t, 2> size = {env.width, env.height};
    words(size.data(), size.size());
    static_assert(sizeof(float) == 4);
    words(env.rgb.data(), env.rgb.size());
    return hasher.value();
}

}  // namespace candela::assets
