#include "textures/webp_image.h"

#include "core/errors.h"

#include <webp/decode.h>
#include <webp/demux.h>

#include <cstring>
#include <memory>
#include <string>

namespace candela::textures {
namespace {

[[noreturn]] void failWebp(const std::string& problem) { throw UserError("WebP: " + problem); }

std::string statusName(VP8StatusCode status) {
    switch (status) {
        case VP8_STATUS_OUT_OF_MEMORY: return "out of memory";
        case VP8_STATUS_INVALID_PARAM: return "invalid parameter";
        case VP8_STATUS_BITSTREAM_ERROR: return "corrupt bitstream";
        case VP8_STATUS_UNSUPPORTED_FEATURE: return "unsupported feature";
        case VP8_STATUS_SUSPENDED: return "suspended";
        case VP8_STATUS_USER_ABORT: return "aborted";
        case VP8_STATUS_NOT_ENOUGH_DATA: return "truncated (not enough data)";
        default: return "error " + std::to_string(int(status));
    }
}

WebPBitstreamFeatures features(std::span<const uint8_t> bytes, uint32_t maxDimension) {
    WebPBitstreamFeatures f{};
    const VP8StatusCode status = WebPGetFeatures(bytes.data(), bytes.size(), &f);
    if (status != VP8_STATUS_OK) failWebp("cannot read the header (" + statusName(status) + ")");
    if (f.width <= 0 || f.height <= 0 || uint32_t(f.width) > maxDimension || uint32_t(f.height) > maxDimension)
        failWebp("image size " + std::to_string(f.width) + "x" + std::to_string(f.height) + " exceeds the limit of " +
             std::to_string(maxDimension) + " pixels per side");
    return f;
}

struct AnimDecoderDelete {
    void operator()(WebPAnimDecoder* decoder) const { WebPAnimDecoderDelete(decoder); }
};

// The first frame of an animation, composited on the canvas as the animation decoder does.
TextureLevel firstFrame(std::span<const uint8_t> bytes) {
    WebPAnimDecoderOptions options;
    if (!WebPAnimDecoderOptionsInit(&options)) failWebp("libwebp's animation decoder has another ABI version");
    options.color_mode = MODE_RGBA;
    options.use_threads = 0;
    const WebPData data{bytes.data(), bytes.size()};
    const std::unique_ptr<WebPAnimDecoder, AnimDecoderDelete> decoder(WebPAnimDecoderNew(&data, &options));
    if (!decoder) failWebp("cannot read the animation");
    WebPAnimInfo info{};
    if (!WebPAnimDecoderGetInfo(decoder.get(), &info) || info.frame_count == 0) failWebp("animation without frames");
    uint8_t* pixels = nullptr;
    int timestamp = 0;
    if (!WebPAnimDecoderGetNext(decoder.get(), &pixels, &timestamp) || !pixels) failWebp("cannot decode the first frame");
    TextureLevel level{info.canvas_width, info.canvas_height, {}};
    level.rgba8.assign(pixels, pixels + size_t(level.width) * level.height * 4);
    return level;
}

}  // namespace

bool isWebp(std::span<const uint8_t> bytes) {
    return bytes.size() >= 12 && std::memcmp(bytes.data(), "RIFF", 4) == 0 && std::memcmp(bytes.data() + 8, "WEBP", 4) == 0;
}

std::pair<uint32_t, uint32_t> webpSize(std::span<const uint8_t> bytes, uint32_t maxDimension) {
    const WebPBitstreamFeatures f = features(bytes, maxDimension);
    return {uint32_t(f.width), uint32_t(f.height)};
}

DecodedTexture decodeWebp(std::span<const uint8_t> bytes, uint32_t maxDimension) {
    const WebPBitstreamFeatures f = features(bytes, maxDimension);
    DecodedTexture out;
    if (f.has_animation) {
        TextureLevel level = firstFrame(bytes);
        if (level.width != uint32_t(f.width) || level.height != uint32_t(f.height)) failWebp("canvas size changed while decoding");
        out.levels.push_back(std::move(level));
        out.report.notes.push_back("animated WebP: drawn from its first frame");
        return out;
    }
    TextureLevel level{uint32_t(f.width), uint32_t(f.height), {}};
    level.rgba8.resize(size_t(level.width) * level.height * 4);
    const int stride = int(level.width * 4);
    if (!WebPDecodeRGBAInto(bytes.data(), bytes.size(), level.rgba8.data(), level.rgba8.size(), stride))
        failWebp("cannot decode the image (corrupt or truncated bitstream)");
    out.levels.push_back(std::move(level));
    return out;
}

}  // namespace candela::textures
