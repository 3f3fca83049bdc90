#include "scene/exr_reader.h"

#include "core/check.h"

#include <tinyexr.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace candela::scene {
namespace {

[[noreturn]] void fail(const std::string& source, const std::string& problem) {
    throw UserError(source + ": " + problem);
}

// tinyexr's messages end in newlines and may hold several lines; ours are one line.
std::string takeMessage(const char* error) {
    std::string out;
    if (error) {
        for (const char* c = error; *c && out.size() < 300; ++c) {
            if (*c == '\n' || *c == '\r') {
                if (!out.empty() && out.back() != ' ') out += "; ";
            } else if (static_cast<unsigned char>(*c) >= 0x20) {
                out += *c;
            }
        }
        FreeEXRErrorMessage(error);
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
    return out.empty() ? std::string("unknown error") : out;
}

// Owns a parsed EXRHeader / loaded EXRImage (tinyexr's C structs).
struct HeaderGuard {
    EXRHeader header;
    HeaderGuard() { InitEXRHeader(&header); }
    ~HeaderGuard() { FreeEXRHeader(&header); }
    HeaderGuard(const HeaderGuard&) = delete;
    HeaderGuard& operator=(const HeaderGuard&) = delete;
};
// tinyexr 1.0.1 frees a partly decoded image itself when LoadEXRImageFromMemory fails, but frees
// only `num_channels` planes (still 0 then) and leaves `images` dangling. So `num_channels` is set
// before loading, and after a failure the guard forgets the image instead of freeing it twice.
struct ImageGuard {
    EXRImage image;
    explicit ImageGuard(int channels) {
        InitEXRImage(&image);
        image.num_channels = channels;
    }
    ~ImageGuard() { FreeEXRImage(&image); }
    void forget() { InitEXRImage(&image); }
    ImageGuard(const ImageGuard&) = delete;
    ImageGuard& operator=(const ImageGuard&) = delete;
};

uint32_t le32(const uint8_t* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24; }

// tinyexr 1.0.1's PIZ decoder copies a chunk's bitmap (whose extent the chunk's first four bytes
// give) without checking that the chunk holds it: a heap over-read found by fuzzing
// (tests/fuzz/regressions/exr/). So the chunks of a PIZ file are checked here before tinyexr
// decodes them: every offset-table entry must name a chunk inside the file, and a compressed
// chunk must hold its bitmap range, bitmap and a Huffman block with its header and a bit count
// that is not negative. Scanline files only; the offset
// table follows the header (8 bytes of magic and version, then header_len bytes).
void checkPizChunks(std::span<const uint8_t> bytes, const EXRHeader& header, int64_t width, int64_t height,
                    const std::string& source) {
    if (header.compression_type != TINYEXR_COMPRESSIONTYPE_PIZ) return;
    constexpr int64_t kLinesPerChunk = 32;
    uint64_t bytesPerLine = 0;
    for (int c = 0; c < header.num_channels; ++c)
        bytesPerLine += uint64_t(width) * (header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF ? 2 : 4);
    const int64_t chunks = (height + kLinesPerChunk - 1) / kLinesPerChunk;
    const uint64_t table = 8 + uint64_t(header.header_len);
    for (int64_t i = 0; i < chunks; ++i) {
        const std::string chunk = "chunk " + std::to_string(i);
        const uint64_t entry = table + uint64_t(i) * 8;
        if (entry + 8 > bytes.size()) fail(source, "truncated EXR offset table");
        const uint64_t offset = uint64_t(le32(&bytes[entry])) | uint64_t(le32(&bytes[entry + 4])) << 32;
        // An entry pointing into the header or the table itself (0 for an unfinished file) would
        // make tinyexr rebuild the table by walking chunk headers, which this check cannot follow.
        if (offset < table + uint64_t(chunks) * 8) fail(source, "EXR offset table entry " + std::to_string(i) + " points into the header");
        if (offset > bytes.size() || bytes.size() - offset < 8) fail(source, "EXR " + chunk + " lies outside the file");
        const uint64_t size = le32(&bytes[offset + 4]);
        if (size > bytes.size() - offset - 8) fail(source, "EXR " + chunk + " runs past the end of the file");
        // tinyexr takes the chunk's line count from the line number the chunk itself states, and
        // decodes a chunk whose size equals those lines uncompressed as stored (no PIZ).
        const int64_t line = int32_t(le32(&bytes[offset]));
        const int64_t lines = std::min(line + kLinesPerChunk, int64_t(header.data_window.max_y) + 1) - line;
        if (lines <= 0) continue;  // tinyexr refuses the chunk
        if (size == uint64_t(lines) * bytesPerLine) continue;
        const uint8_t* data = &bytes[offset + 8];
        if (size < 8) fail(source, "corrupt PIZ data in EXR " + chunk);
        const uint32_t minNonZero = uint32_t(data[0]) | uint32_t(data[1]) << 8;
        const uint32_t maxNonZero = uint32_t(data[2]) | uint32_t(data[3]) << 8;
        const uint64_t bitmap = minNonZero <= maxNonZero ? maxNonZero - minNonZero + 1 : 0;
        if (4 + bitmap + 4 > size) fail(source, "corrupt PIZ data in EXR " + chunk + " (bitmap past the chunk's end)");
        // Then the Huffman block: its length, and a 20-byte header whose fourth word is the bit
        // count. tinyexr reads that header without checking the length and computes with a
        // negative bit count in signed overflow (a second fuzz finding).
        const uint8_t* huffman = data + 4 + bitmap;
        const int32_t length = int32_t(le32(huffman));
        if (length < 20 || uint64_t(length) > size - (4 + bitmap + 4))
            fail(source, "corrupt PIZ data in EXR " + chunk + " (Huffman block length " + std::to_string(length) + ")");
        if (int32_t(le32(huffman + 4 + 12)) < 0)
            fail(source, "corrupt PIZ data in EXR " + chunk + " (negative Huffman bit count)");
    }
}

}  // namespace

bool looksLikeExr(std::span<const uint8_t> bytes) {
    return bytes.size() >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

Environment decodeExr(std::span<const uint8_t> bytes, const std::string& source, const EnvironmentLoadOptions& options) {
    if (!looksLikeExr(bytes)) fail(source, "not an OpenEXR file (bad magic number)");
    EXRVersion version;
    if (ParseEXRVersionFromMemory(&version, bytes.data(), bytes.size()) != TINYEXR_SUCCESS)
        fail(source, bytes.size() < 8 ? "truncated EXR (" + std::to_string(bytes.size()) + " bytes)"
                                      : "unsupported OpenEXR version field");
    if (version.multipart) fail(source, "multi-part EXR is not supported");
    if (version.non_image) fail(source, "deep EXR is not supported");
    if (version.tiled) fail(source, "tiled EXR is not supported (save it with scanlines)");

    HeaderGuard parsed;
    EXRHeader& header = parsed.header;
    const char* error = nullptr;
    if (ParseEXRHeaderFromMemory(&header, &version, bytes.data(), bytes.size(), &error) != TINYEXR_SUCCESS)
        fail(source, "invalid EXR header: " + takeMessage(error));
    if (header.tiled) fail(source, "tiled EXR is not supported (save it with scanlines)");

    // 64-bit arithmetic: the window's corners are arbitrary 32-bit integers.
    const EXRBox2i& window = header.data_window;
    const int64_t width = int64_t(window.max_x) - window.min_x + 1;
    const int64_t height = int64_t(window.max_y) - window.min_y + 1;
    if (width <= 0 || height <= 0)
        fail(source, "empty or inverted EXR data window (" + std::to_string(window.min_x) + "," +
                         std::to_string(window.min_y) + ")-(" + std::to_string(window.max_x) + "," +
                         std::to_string(window.max_y) + ")");
    checkEnvironmentSize(source, uint64_t(width), uint64_t(height), options);

    // R, G, B (or Y for grey); everything else is ignored.
    std::array<int, 3> rgb = {-1, -1, -1};
    int grey = -1;
    for (int c = 0; c < header.num_channels; ++c) {
        const char* name = header.channels[c].name;
        const int index = !std::strcmp(name, "R") ? 0 : !std::strcmp(name, "G") ? 1 : !std::strcmp(name, "B") ? 2 : -1;
        if (index < 0 && std::strcmp(name, "Y")) continue;
        if (header.pixel_types[c] != TINYEXR_PIXELTYPE_HALF && header.pixel_types[c] != TINYEXR_PIXELTYPE_FLOAT)
            fail(source, std::string("channel ") + name + " is UINT; only HALF and FLOAT are supported");
        if (header.channels[c].x_sampling != 1 || header.channels[c].y_sampling != 1)
            fail(source, std::string("channel ") + name + " is sub-sampled; not supported");
        if (index >= 0) rgb[size_t(index)] = c;
        else grey = c;
        header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
    }
    if (rgb[0] < 0 || rgb[1] < 0 || rgb[2] < 0) {
        if (grey < 0) fail(source, "no R, G, B (or Y) channels");
        rgb = {grey, grey, grey};
    }

    checkPizChunks(bytes, header, width, height, source);
    ImageGuard loaded(header.num_channels);
    EXRImage& image = loaded.image;
    if (LoadEXRImageFromMemory(&image, &header, bytes.data(), bytes.size(), &error) != TINYEXR_SUCCESS) {
        loaded.forget();
        fail(source, "cannot decode EXR pixels: " + takeMessage(error));
    }
    if (!image.images || image.width != width || image.height != height)
        fail(source, "cannot decode EXR pixels: unexpected image layout");

    Environment env;
    env.source = source;
    env.width = uint32_t(width);
    env.height = uint32_t(height);
    env.rgb.resize(env.texelCount() * 3);
    const size_t count = env.texelCount();
    for (size_t c = 0; c < 3; ++c) {
        const float* plane = reinterpret_cast<const float*>(image.images[rgb[c]]);
        for (size_t i = 0; i < count; ++i) env.rgb[i * 3 + c] = plane[i];
    }
    return env;
}

}  // namespace candela::scene
