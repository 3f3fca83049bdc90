#pragma once
// WebP files for the tests, written with Debian's libwebp encoder (and libwebpmux's animation
// encoder): lossless with exact RGB under transparent pixels, lossy with or without alpha, and a
// two-frame animation.

#include <webp/encode.h>
#include <webp/mux.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace candela::test {

// `rgba`: width × height × 4 bytes. Lossless keeps every byte, the RGB of transparent texels too
// (config.exact); lossy uses `quality` for RGB and keeps alpha lossless.
inline std::vector<uint8_t> encodeWebp(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba,
                                       bool lossless, float quality = 90.0f) {
    WebPConfig config;
    if (!WebPConfigInit(&config)) throw std::runtime_error("WebPConfigInit");
    config.lossless = lossless ? 1 : 0;
    config.exact = 1;
    config.quality = lossless ? 100.0f : quality;
    config.alpha_quality = 100;
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw std::runtime_error("WebPPictureInit");
    picture.use_argb = 1;
    picture.width = int(width);
    picture.height = int(height);
    if (!WebPPictureImportRGBA(&picture, rgba.data(), int(width * 4))) throw std::runtime_error("WebPPictureImportRGBA");
    WebPMemoryWriter writer;
    WebPMemoryWriterInit(&writer);
    picture.writer = WebPMemoryWrite;
    picture.custom_ptr = &writer;
    const bool ok = WebPEncode(&config, &picture) != 0;
    WebPPictureFree(&picture);
    std::vector<uint8_t> out(writer.mem, writer.mem + writer.size);
    WebPMemoryWriterClear(&writer);
    if (!ok) throw std::runtime_error("WebPEncode");
    return out;
}

// A lossless animation of the given frames (each width × height × 4 bytes), 100 ms apart.
inline std::vector<uint8_t> encodeAnimatedWebp(uint32_t width, uint32_t height, const std::vector<std::vector<uint8_t>>& frames) {
    WebPAnimEncoderOptions options;
    if (!WebPAnimEncoderOptionsInit(&options)) throw std::runtime_error("WebPAnimEncoderOptionsInit");
    WebPAnimEncoder* encoder = WebPAnimEncoderNew(int(width), int(height), &options);
    if (!encoder) throw std::runtime_error("WebPAnimEncoderNew");
    WebPConfig config;
    WebPConfigInit(&config);
    config.lossless = 1;
    config.exact = 1;
    int timestamp = 0;
    for (const std::vector<uint8_t>& frame : frames) {
        WebPPicture picture;
        WebPPictureInit(&picture);
        picture.use_argb = 1;
        picture.width = int(width);
        picture.height = int(height);
        WebPPictureImportRGBA(&picture, frame.data(), int(width * 4));
        const bool ok = WebPAnimEncoderAdd(encoder, &picture, timestamp, &config) != 0;
        WebPPictureFree(&picture);
        if (!ok) throw std::runtime_error("WebPAnimEncoderAdd");
        timestamp += 100;
    }
    WebPAnimEncoderAdd(encoder, nullptr, timestamp, nullptr);
    WebPData data;
    WebPDataInit(&data);
    const bool ok = WebPAnimEncoderAssemble(encoder, &data) != 0;
    std::vector<uint8_t> out(data.bytes, data.bytes + data.size);
    WebPDataClear(&data);
    WebPAnimEncoderDelete(encoder);
    if (!ok) throw std::runtime_error("WebPAnimEncoderAssemble");
    return out;
}

}  // namespace candela::test
