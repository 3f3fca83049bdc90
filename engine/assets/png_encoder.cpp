#include "assets/png_encoder.h"

#include "core/errors.h"

#include <zlib.h>

#include <array>
#include <cstdlib>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace candela::assets {

namespace {

void putU32(std::vector<uint8_t>& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(v >> shift));
}

// Appends a chunk: length, type, data, CRC-32 of type and data.
void putChunk(std::vector<uint8_t>& out, const char (&type)[5], std::span<const uint8_t> data) {
    putU32(out, uint32_t(data.size()));
    const size_t typeAt = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    putU32(out, uint32_t(crc32(0, out.data() + typeAt, uInt(out.size() - typeAt))));
}

uint8_t paeth(int a, int b, int c) {
    const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    return uint8_t(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

}  // namespace

std::vector<uint8_t> encodePng(uint32_t width, uint32_t height, std::span<const uint8_t> rgba) {
    const size_t stride = size_t(width) * 4;
    if (width == 0 || height == 0 || rgba.size() != stride * height) throw InternalError("encodePng: pixels do not match the size");
    // Filtered rows: a filter-type byte (4: Paeth) then each byte less its Paeth predictor from the
    // byte to its left (a), above (b) and above-left (c), 0 outside the image.
    // Buffers left uninitialized: every byte is written before it is read, and zeroing them first
    // would touch (and fault in) the deflate bound's pages that are never used.
    const size_t filteredBytes = (stride + 1) * height;
    const std::unique_ptr<uint8_t[]> filtered(new uint8_t[filteredBytes]);
    for (uint32_t y = 0; y < height; ++y) {
        const uint8_t* row = rgba.data() + y * stride;
        const uint8_t* above = y > 0 ? row - stride : nullptr;
        uint8_t* out = filtered.get() + y * (stride + 1);
        *out++ = 4;
        for (size_t i = 0; i < stride; ++i) {
            const int a = i >= 4 ? row[i - 4] : 0, b = above ? above[i] : 0, c = above && i >= 4 ? above[i - 4] : 0;
            out[i] = uint8_t(row[i] - paeth(a, b, c));
        }
    }
    // The stream ends with the scope, also when an allocation below throws.
    struct Deflater {
        z_stream stream{};
        ~Deflater() { deflateEnd(&stream); }
    } deflater;
    z_stream& stream = deflater.stream;
    if (deflateInit2(&stream, 1, Z_DEFLATED, 15, 9, Z_RLE) != Z_OK) throw InternalError("encodePng: deflateInit2 failed");
    const uLong bound = deflateBound(&stream, uLong(filteredBytes));
    const std::unique_ptr<uint8_t[]> deflatedBytes(new uint8_t[bound]);
    stream.next_in = filtered.get();
    stream.avail_in = uInt(filteredBytes);
    stream.next_out = deflatedBytes.get();
    stream.avail_out = uInt(bound);
    const int result = deflate(&stream, Z_FINISH);
    const std::span<const uint8_t> deflated(deflatedBytes.get(), stream.total_out);
    if (result != Z_STREAM_END) throw InternalError("encodePng: deflate failed (" + std::to_string(result) + ")");

    std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    png.reserve(png.size() + deflated.size() + 64);
    std::vector<uint8_t> header;
    putU32(header, width);
    putU32(header, height);
    header.insert(header.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, adaptive filtering, no interlace
    putChunk(png, "IHDR", header);
    putChunk(png, "IDAT", deflated);
    putChunk(png, "IEND", {});
    return png;
}

}  // namespace candela::assets
