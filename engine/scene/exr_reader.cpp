#include "scene/exr_reader.h"

#include "core/check.h"

#include <tinyexr.h>

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
