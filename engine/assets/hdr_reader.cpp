#include "assets/hdr_reader.h"

#include "core/errors.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string_view>

namespace candela::assets {
namespace {

constexpr size_t kMaxHeaderBytes = 64 * 1024;
constexpr uint32_t kMinRleWidth = 8;       // Radiance writes shorter scanlines flat
constexpr uint32_t kMaxRleWidth = 0x7fff;  // the RLE marker stores the width in 15 bits

[[noreturn]] void failHdr(const std::string& source, const std::string& problem) {
    throw UserError(source + ": " + problem);
}

// Header text quoted in a message: printable ASCII only, at most 60 characters.
std::string quoted(std::string_view text) {
    std::string out;
    for (char c : text.substr(0, 60)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
    if (text.size() > 60) out += "...";
    return "'" + out + "'";
}

// Bounds-checked reading through the file's bytes.
class Cursor {
public:
    Cursor(std::span<const uint8_t> bytes, const std::string& source) : mBytes(bytes), mSource(source) {}

    size_t offset() const { return mOffset; }
    size_t remaining() const { return mBytes.size() - mOffset; }
    const uint8_t* at() const { return mBytes.data() + mOffset; }

    // The next line without its '\n' (and a trailing '\r'), or nullopt if no '\n' follows.
    std::optional<std::string_view> line(size_t maxLength) {
        const size_t limit = std::min(remaining(), maxLength + 1);
        const void* newline = std::memchr(at(), '\n', limit);
        if (!newline) return std::nullopt;
        const size_t length = static_cast<size_t>(static_cast<const uint8_t*>(newline) - at());
        std::string_view text(reinterpret_cast<const char*>(at()), length);
        mOffset += length + 1;
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        return text;
    }

    // Takes `count` bytes, or throws "truncated" naming scanline `row` of `rows`.
    const uint8_t* take(size_t count, uint32_t row, uint32_t rows) {
        if (count > remaining())
            failHdr(mSource, "truncated: the file ends (" + std::to_string(mBytes.size()) + " bytes) inside scanline " +
                              std::to_string(row) + " of " + std::to_string(rows));
        const uint8_t* p = at();
        mOffset += count;
        return p;
    }

private:
    std::span<const uint8_t> mBytes;
    const std::string& mSource;
    size_t mOffset = 0;
};

struct Header {
    uint32_t width = 0, height = 0;
    bool flipX = false;  // -X: scanlines run right to left
    bool flipY = false;  // +Y: the first scanline is the bottom row
    double exposure = 1.0;
};

// "±A N" → axis, sign, value; false when malformed.
bool parseAxis(std::string_view sign, std::string_view number, char& axis, bool& positive, uint64_t& value) {
    if (sign.size() != 2 || (sign[0] != '+' && sign[0] != '-') || (sign[1] != 'X' && sign[1] != 'Y')) return false;
    if (number.empty() || number.size() > 12) return false;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (ec != std::errc() || end != number.data() + number.size()) return false;
    axis = sign[1];
    positive = sign[0] == '+';
    return true;
}

std::vector<std::string_view> splitWords(std::string_view text) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
        const size_t begin = i;
        while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
        if (i > begin) words.push_back(text.substr(begin, i - begin));
    }
    return words;
}

Header parseHeader(Cursor& cursor, const std::string& source, const EnvironmentLoadOptions& options) {
    Header header;
    auto nextLine = [&](const char* missing) {
        const std::optional<std::string_view> line = cursor.line(kMaxHeaderBytes);
        if (!line && cursor.remaining() > kMaxHeaderBytes)
            failHdr(source, "header line longer than " + std::to_string(kMaxHeaderBytes) + " bytes");
        if (!line) failHdr(source, missing);
        return *line;
    };
    nextLine("truncated header (no end of the first line)");
    bool haveFormat = false;
    for (;;) {
        if (cursor.offset() > kMaxHeaderBytes)
            failHdr(source, "header longer than " + std::to_string(kMaxHeaderBytes) + " bytes (no blank line ending it)");
        const std::string_view line = nextLine("truncated header (no blank line ending it)");
        if (line.empty()) break;
        if (line.front() == '#') continue;  // comments, repeated "#?RADIANCE"
        if (line.starts_with("FORMAT=")) {
            std::string_view format = line.substr(7);
            while (!format.empty() && (format.back() == ' ' || format.back() == '\t')) format.remove_suffix(1);
            if (format == "32-bit_rle_xyze")
                failHdr(source, "FORMAT=32-bit_rle_xyze (CIE XYZ) is not supported; only 32-bit_rle_rgbe");
            if (format != "32-bit_rle_rgbe")
                failHdr(source, "unsupported FORMAT=" + quoted(format) + "; only 32-bit_rle_rgbe");
            haveFormat = true;
        } else if (line.starts_with("EXPOSURE=")) {
            // EXPOSURE values are cumulative (Radiance's definition).
            const std::string value(line.substr(9));
            char* end = nullptr;
            const double exposure = std::strtod(value.c_str(), &end);
            if (end != value.c_str() && std::isfinite(exposure) && exposure > 0.0) header.exposure *= exposure;
        }
        // Everything else (GAMMA=, PRIMARIES=, VIEW=, SOFTWARE=, command lines) does not change
        // how the pixels decode.
    }
    if (!haveFormat) failHdr(source, "no FORMAT= line in the header (expected FORMAT=32-bit_rle_rgbe)");

    const std::optional<std::string_view> resolution = cursor.line(256);
    if (!resolution && cursor.remaining() > 256) failHdr(source, "bad resolution line (no end of line within 256 bytes)");
    if (!resolution) failHdr(source, "truncated: no resolution line after the header");
    const std::vector<std::string_view> words = splitWords(*resolution);
    char axis1 = 0, axis2 = 0;
    bool positive1 = false, positive2 = false;
    uint64_t size1 = 0, size2 = 0;
    if (words.size() != 4 || !parseAxis(words[0], words[1], axis1, positive1, size1) ||
        !parseAxis(words[2], words[3], axis2, positive2, size2) || axis1 == axis2)
        failHdr(source, "bad resolution line " + quoted(*resolution) + " (expected e.g. '-Y 512 +X 1024')");
    if (axis1 == 'X')
        failHdr(source, "unsupported orientation " + quoted(*resolution) +
                         " (transposed: scanlines are columns); only '±Y H ±X W' is read");
    checkEnvironmentSize(source, size2, size1, options);
    header.width = static_cast<uint32_t>(size2);
    header.height = static_cast<uint32_t>(size1);
    header.flipY = positive1;
    header.flipX = !positive2;
    return header;
}

// New-style RLE: four channel planes of runs (count > 128: repeat the next byte count − 128 times)
// and literals (count ≤ 128: copy count bytes). `out` receives 4 × width interleaved RGBE bytes.
void readRleScanline(Cursor& cursor, const std::string& source, uint8_t* out, uint32_t width, uint32_t row,
                     uint32_t rows) {
    for (uint32_t channel = 0; channel < 4; ++channel) {
        uint32_t x = 0;
        while (x < width) {
            const uint8_t count = *cursor.take(1, row, rows);
            const bool run = count > 128;
            const uint32_t length = run ? count - 128u : count;
            if (length == 0) failHdr(source, "scanline " + std::to_string(row) + ": zero-length RLE literal");
            if (length > width - x)
                failHdr(source, "RLE " + std::string(run ? "run" : "literal") + " of " + std::to_string(length) +
                                 " at x = " + std::to_string(x) + " overflows scanline " + std::to_string(row) +
                                 " (width " + std::to_string(width) + ")");
            const uint8_t* data = cursor.take(run ? 1 : length, row, rows);
            for (uint32_t i = 0; i < length; ++i) out[size_t(x + i) * 4 + channel] = run ? data[0] : data[i];
            x += length;
        }
    }
}

// Flat texels, with old-style RLE repeat markers (1,1,1,n): repeat the previous texel n << shift
// times, shift growing by 8 for consecutive markers. `previous` is the texel before `out` in file
// order (nullptr at the very start).
void readFlatScanline(Cursor& cursor, const std::string& source, uint8_t* out, const uint8_t* previous,
                      uint32_t width, uint32_t row, uint32_t rows) {
    uint32_t x = 0;
    uint32_t shift = 0;
    while (x < width) {
        const uint8_t* texel = cursor.take(4, row, rows);
        if (texel[0] == 1 && texel[1] == 1 && texel[2] == 1) {
            const uint64_t count = texel[3] == 0 ? 0 : shift > 24 ? UINT64_MAX : uint64_t(texel[3]) << shift;
            if (count > width - x)
                failHdr(source, "old-style RLE repeat of " + std::to_string(count) + " at x = " + std::to_string(x) +
                                 " overflows scanline " + std::to_string(row) + " (width " + std::to_string(width) +
                                 ")");
            const uint8_t* from = x > 0 ? out + size_t(x - 1) * 4 : previous;
            if (!from && count > 0) failHdr(source, "old-style RLE repeat before the first texel");
            for (uint64_t i = 0; i < count; ++i) std::memcpy(out + (x + i) * 4, from, 4);
            x += static_cast<uint32_t>(count);
            shift += 8;
        } else {
            std::memcpy(out + size_t(x) * 4, texel, 4);
            ++x;
            shift = 0;
        }
    }
}

}  // namespace

bool looksLikeHdr(std::span<const uint8_t> bytes) { return bytes.size() >= 2 && bytes[0] == '#' && bytes[1] == '?'; }

Environment decodeHdr(std::span<const uint8_t> bytes, const std::string& source, const EnvironmentLoadOptions& options) {
    if (!looksLikeHdr(bytes)) failHdr(source, "not a Radiance HDR file (it does not start with '#?')");
    Cursor cursor(bytes, source);
    const Header header = parseHeader(cursor, source, options);
    const uint32_t width = header.width, height = header.height;

    // RGBE bytes in file order, grown scanline by scanline: a truncated file claiming a huge size
    // fails before the memory is committed.
    std::vector<uint8_t> rgbe;
    const size_t rowBytes = size_t(width) * 4;
    for (uint32_t row = 0; row < height; ++row) {
        rgbe.resize(rgbe.size() + rowBytes);
        uint8_t* out = rgbe.data() + size_t(row) * rowBytes;
        const uint8_t* p = cursor.at();
        if (width >= kMinRleWidth && width <= kMaxRleWidth && cursor.remaining() >= 4 && p[0] == 2 && p[1] == 2 &&
            !(p[2] & 0x80)) {
            const uint32_t length = uint32_t(p[2]) << 8 | p[3];
            if (length != width)
                failHdr(source, "scanline " + std::to_string(row) + ": RLE length " + std::to_string(length) +
                                 " does not match the width " + std::to_string(width));
            cursor.take(4, row, height);
            readRleScanline(cursor, source, out, width, row, height);
        } else {
            readFlatScanline(cursor, source, out, row > 0 ? out - 4 : nullptr, width, row, height);
        }
    }

    std::array<float, 256> scale{};
    for (int e = 1; e < 256; ++e) scale[size_t(e)] = std::ldexp(1.0f, e - 136);
    Environment env;
    env.source = source;
    env.width = width;
    env.height = height;
    env.rgb.resize(env.texelCount() * 3);
    for (uint32_t row = 0; row < height; ++row) {
        const uint32_t y = header.flipY ? height - 1 - row : row;
        for (uint32_t col = 0; col < width; ++col) {
            const uint32_t x = header.flipX ? width - 1 - col : col;
            const uint8_t* in = rgbe.data() + size_t(row) * rowBytes + size_t(col) * 4;
            float* texel = env.texel(x, y);
            const float s = scale[in[3]];
            for (int c = 0; c < 3; ++c) texel[c] = float(in[c]) * s;
        }
    }
    if (header.exposure != 1.0) {
        char exposure[32];
        std::snprintf(exposure, sizeof exposure, "%g", header.exposure);
        env.report.warnings.push_back(source + ": EXPOSURE=" + exposure +
                               " in the header is ignored (texels are used as stored, as other viewers do)");
    }
    return env;
}

}  // namespace candela::assets
