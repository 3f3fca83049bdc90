#include "assets/png_encoder.h"

#include "core/errors.h"
#include "core/parallel_for.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <limits>
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

// Rows per piece deflated on its own (encodePng): 1280 × 720 makes 12 pieces of ~300 KiB.
constexpr uint32_t kPieceRows = 64;

uint8_t paeth(int a, int b, int c) {
    const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    return uint8_t(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

// Vectors of 8 bytes and of 8 signed 16-bit lanes (GCC/Clang vector extensions).
using Bytes8 = uint8_t __attribute__((vector_size(8)));
using Shorts8 = int16_t __attribute__((vector_size(16)));

Shorts8 absolute(Shorts8 v) { return v < 0 ? -v : v; }

// out[0, 8) = row[k] − paeth(row[k − 4], above[k], above[k − 4]) for k in [0, 8): paeth's choice
// lane by lane, without a branch. Precondition: row and above have 4 bytes before them.
void paeth8(const uint8_t* row, const uint8_t* above, uint8_t* out) {
    Bytes8 x, left, up, upLeft;
    std::memcpy(&x, row, 8);
    std::memcpy(&left, row - 4, 8);
    std::memcpy(&up, above, 8);
    std::memcpy(&upLeft, above - 4, 8);
    const Shorts8 a = __builtin_convertvector(left, Shorts8), b = __builtin_convertvector(up, Shorts8),
                  c = __builtin_convertvector(upLeft, Shorts8);
    const Shorts8 pa = absolute(b - c), pb = absolute(a - c), pc = absolute(a + b - c - c);  // |p − a|, |p − b|, |p − c|
    const Shorts8 predictor = ((pa <= pb) & (pa <= pc)) ? a : (pb <= pc ? b : c);
    const Bytes8 residual = x - __builtin_convertvector(predictor, Bytes8);
    std::memcpy(out, &residual, 8);
}

}  // namespace

std::vector<uint8_t> encodePng(uint32_t width, uint32_t height, std::span<const uint8_t> rgba) {
    const size_t stride = size_t(width) * 4;
    if (width == 0 || height == 0 || rgba.size() != stride * height) throw InternalError("encodePng: pixels do not match the size");
    // Filtered rows: a filter-type byte (4: Paeth) then each byte less its Paeth predictor from the
    // byte to its left (a), above (b) and above-left (c), 0 outside the image. Rows on every core.
    // Buffers left uninitialized: every byte is written before it is read, and zeroing them first
    // would touch (and fault in) the deflate bound's pages that are never used.
    const size_t filteredBytes = (stride + 1) * height;
    const std::unique_ptr<uint8_t[]> filtered(new uint8_t[filteredBytes]);
    parallelForRows(width * 4, height, [&](uint32_t y) {
        const uint8_t* row = rgba.data() + y * stride;
        const uint8_t* above = y > 0 ? row - stride : nullptr;
        uint8_t* out = filtered.get() + y * (stride + 1);
        *out++ = 4;
        size_t i = 0;
        for (; i < std::min<size_t>(stride, 4); ++i) out[i] = uint8_t(row[i] - paeth(0, above ? above[i] : 0, 0));
        if (above)
            for (; i + 8 <= stride; i += 8) paeth8(row + i, above + i, out + i);
        for (; i < stride; ++i) {
            const int a = row[i - 4], b = above ? above[i] : 0, c = above ? above[i - 4] : 0;
            out[i] = uint8_t(row[i] - paeth(a, b, c));
        }
    });
    // Deflated in pieces of kPieceRows rows on every core, each its own raw deflate stream, the
    // pieces but the last ending on a byte with a sync flush (as pigz does): joined, they are one
    // zlib stream. Z_RLE's matches are runs at distance 1, so a piece loses only its first byte's
    // run to the cut. The pieces depend on the image alone: the file is the same whatever the core
    // count (for the same zlib).
    const size_t pieceBytes = size_t(kPieceRows) * (stride + 1);
    if (pieceBytes > std::numeric_limits<uInt>::max() / 2) throw InternalError("encodePng: rows too wide for a deflate piece");
    const size_t pieces = (filteredBytes + pieceBytes - 1) / pieceBytes;
    struct Piece {
        std::unique_ptr<uint8_t[]> bytes;  // uninitialized, as `filtered`
        size_t size = 0;
        size_t rowsBytes = 0;  // of the filtered rows it holds
        uLong adler = 0;       // of those rows
    };
    std::vector<Piece> deflated(pieces);
    parallelFor(pieces, [&](size_t p) {
        const size_t begin = p * pieceBytes, bytes = std::min(pieceBytes, filteredBytes - begin);
        const bool last = p + 1 == pieces;
        // The stream ends with the scope, also when an allocation below throws.
        struct Deflater {
            z_stream stream{};
            ~Deflater() { deflateEnd(&stream); }
        } deflater;
        z_stream& stream = deflater.stream;
        if (deflateInit2(&stream, 1, Z_DEFLATED, -15, 9, Z_RLE) != Z_OK) throw InternalError("encodePng: deflateInit2 failed");
        Piece& out = deflated[p];
        const size_t bound = deflateBound(&stream, uLong(bytes)) + 16;  // + a sync flush's empty stored block
        out.bytes.reset(new uint8_t[bound]);
        stream.next_in = filtered.get() + begin;
        stream.avail_in = uInt(bytes);
        stream.next_out = out.bytes.get();
        stream.avail_out = uInt(bound);
        const int result = deflate(&stream, last ? Z_FINISH : Z_SYNC_FLUSH);
        // A sync flush that filled the buffer exactly may not have written all of itself.
        if (result != (last ? Z_STREAM_END : Z_OK) || stream.avail_in != 0 || stream.avail_out == 0)
            throw InternalError("encodePng: deflate failed (" + std::to_string(result) + ")");
        out.size = stream.total_out;
        out.rowsBytes = bytes;
        out.adler = adler32(adler32(0, nullptr, 0), filtered.get() + begin, uInt(bytes));
    });
    // The zlib stream: its header (deflate, 32 KiB window, level 1's "fastest" flag), the pieces,
    // and the Adler-32 of all the filtered rows, combined from the pieces'.
    std::vector<uint8_t> idat = {0x78, 0x01};
    size_t idatBytes = 2 + 4;
    for (const Piece& piece : deflated) idatBytes += piece.size;
    idat.reserve(idatBytes);
    uLong adler = deflated[0].adler;
    for (size_t p = 0; p < pieces; ++p) {
        idat.insert(idat.end(), deflated[p].bytes.get(), deflated[p].bytes.get() + deflated[p].size);
        if (p > 0) adler = adler32_combine(adler, deflated[p].adler, z_off_t(deflated[p].rowsBytes));
    }
    putU32(idat, uint32_t(adler));

    std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    png.reserve(png.size() + idat.size() + 64);
    std::vector<uint8_t> header;
    putU32(header, width);
    putU32(header, height);
    header.insert(header.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, adaptive filtering, no interlace
    putChunk(png, "IHDR", header);
    putChunk(png, "IDAT", idat);
    putChunk(png, "IEND", {});
    return png;
}

}  // namespace candela::assets
