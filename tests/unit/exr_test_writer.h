#pragma once
// OpenEXR files in memory for the tests and the fuzz seeds, written through OpenEXR's C++ library:
// an implementation independent of the reader under test (engine/assets/exr_reader.cpp uses
// OpenEXRCore). Any compression, scanline or tiled (any level mode), HALF/FLOAT/UINT and
// sub-sampled channels, data and display windows, several parts, deep parts.

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDeepFrameBuffer.h>
#include <OpenEXR/ImfDeepScanLineOutputPart.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfOutputPart.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfTiledOutputPart.h>
#include <Imath/half.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace candela::test {

enum class ExrType { Half, Float, Uint };

struct ExrChannel {
    std::string name;
    ExrType type = ExrType::Float;  // stored type; values are given as floats (UINT: whole numbers)
    std::vector<float> values;      // one per sample of the data window, top row first
    int sampling = 1;               // x and y sub-sampling (values then hold (w/s) × (h/s) samples)
};

struct ExrLayout {
    Imf::Compression compression = Imf::ZIP_COMPRESSION;
    bool tiled = false;
    int tileSize = 16;
    Imf::LevelMode levels = Imf::ONE_LEVEL;  // tiled: the levels below the first hold zeros
    int dataX = 0, dataY = 0;                // the data window's top-left corner
    std::optional<Imath::Box2i> display;     // the display window; the data window when absent
};

struct ExrPart {
    std::string name;
    uint32_t width = 0, height = 0;  // the data window's size
    std::vector<ExrChannel> channels;
    ExrLayout layout;
    bool deep = false;  // one sample per pixel, scanlines (compression none, RLE or ZIPS only)
};

namespace exr_detail {

inline Imf::PixelType pixelType(ExrType type) {
    return type == ExrType::Half ? Imf::HALF : type == ExrType::Float ? Imf::FLOAT : Imf::UINT;
}

// What a part's frame buffer points at: every channel in its stored type (OpenEXR writes only
// from slices of the channel's own type).
struct Planes {
    std::vector<std::vector<float>> floats;
    std::vector<std::vector<Imath::half>> halves;
    std::vector<std::vector<uint32_t>> uints;
    explicit Planes(const ExrPart& part)
        : floats(part.channels.size()), halves(part.channels.size()), uints(part.channels.size()) {
        for (size_t c = 0; c < part.channels.size(); ++c) {
            const ExrChannel& channel = part.channels[c];
            if (channel.type == ExrType::Uint) uints[c].assign(channel.values.begin(), channel.values.end());
            else if (channel.type == ExrType::Half) halves[c].assign(channel.values.begin(), channel.values.end());
            else floats[c] = channel.values;
        }
    }
    const void* base(size_t c, ExrType type) const {
        return type == ExrType::Uint   ? static_cast<const void*>(uints[c].data())
               : type == ExrType::Half ? static_cast<const void*>(halves[c].data())
                                       : static_cast<const void*>(floats[c].data());
    }
};

inline Imf::Header header(const ExrPart& part, bool multiPart, bool anyDeep) {
    const ExrLayout& layout = part.layout;
    const Imath::Box2i data({layout.dataX, layout.dataY},
                            {layout.dataX + int(part.width) - 1, layout.dataY + int(part.height) - 1});
    Imf::Header header(layout.display.value_or(data), data);
    header.compression() = layout.compression;
    for (const ExrChannel& channel : part.channels)
        header.channels().insert(channel.name, Imf::Channel(pixelType(channel.type), channel.sampling, channel.sampling));
    if (layout.tiled) header.setTileDescription(Imf::TileDescription(layout.tileSize, layout.tileSize, layout.levels));
    header.setType(part.deep ? Imf::DEEPSCANLINE : layout.tiled ? Imf::TILEDIMAGE : Imf::SCANLINEIMAGE);
    // The deep data format's version: OpenEXRCore 3.1 requires it on every part of a file that
    // holds deep data (the C++ library writes it on deep parts only).
    if (anyDeep) header.setVersion(1);
    if (multiPart) header.setName(part.name);
    return header;
}

inline Imf::FrameBuffer frameBuffer(const ExrPart& part, Planes& planes, const Imath::Box2i& data) {
    Imf::FrameBuffer frame;
    for (size_t c = 0; c < part.channels.size(); ++c) {
        const ExrChannel& channel = part.channels[c];
        frame.insert(channel.name, Imf::Slice::Make(pixelType(channel.type), planes.base(c, channel.type), data, 0, 0,
                                                    channel.sampling, channel.sampling));
    }
    return frame;
}

inline void writeDeep(Imf::MultiPartOutputFile& file, int index, const ExrPart& part, Planes& planes) {
    Imf::DeepScanLineOutputPart out(file, index);
    const size_t pixels = size_t(part.width) * part.height;
    std::vector<uint32_t> counts(pixels, 1);
    std::vector<std::vector<const char*>> pointers(part.channels.size(), std::vector<const char*>(pixels));
    Imf::DeepFrameBuffer frame;
    const Imath::Box2i data = out.header().dataWindow();
    frame.insertSampleCountSlice(Imf::Slice::Make(Imf::UINT, counts.data(), data));
    for (size_t c = 0; c < part.channels.size(); ++c) {
        const ExrType type = part.channels[c].type;
        const size_t size = type == ExrType::Half ? 2 : 4;
        for (size_t i = 0; i < pixels; ++i) pointers[c][i] = static_cast<const char*>(planes.base(c, type)) + i * size;
        char* base = reinterpret_cast<char*>(pointers[c].data()) -
                     (ptrdiff_t(data.min.x) + ptrdiff_t(data.min.y) * part.width) * ptrdiff_t(sizeof(char*));
        frame.insert(part.channels[c].name, Imf::DeepSlice(pixelType(type), base, sizeof(char*), sizeof(char*) * part.width, size));
    }
    out.setFrameBuffer(frame);
    out.writePixels(int(part.height));
}

}  // namespace exr_detail

// The parts in order, as one file: a single-part file for one part, multi-part otherwise.
inline std::vector<uint8_t> makeExrParts(const std::vector<ExrPart>& parts) {
    std::vector<Imf::Header> headers;
    const bool anyDeep = std::any_of(parts.begin(), parts.end(), [](const ExrPart& p) { return p.deep; });
    for (const ExrPart& part : parts) headers.push_back(exr_detail::header(part, parts.size() > 1, anyDeep));
    Imf::StdOSStream stream;
    {
        Imf::MultiPartOutputFile file(stream, headers.data(), int(headers.size()));
        for (size_t p = 0; p < parts.size(); ++p) {
            const ExrPart& part = parts[p];
            exr_detail::Planes planes(part);
            const Imath::Box2i data = headers[p].dataWindow();
            if (part.deep) {
                exr_detail::writeDeep(file, int(p), part, planes);
            } else if (part.layout.tiled) {
                Imf::TiledOutputPart out(file, int(p));
                out.setFrameBuffer(exr_detail::frameBuffer(part, planes, data));
                out.writeTiles(0, out.numXTiles(0) - 1, 0, out.numYTiles(0) - 1, 0, 0);
                // The smaller levels, from a zero frame buffer of the full size (4 bytes a sample
                // whatever the type; only the types must match).
                std::vector<uint32_t> zeros(size_t(part.width) * part.height, 0u);
                Imf::FrameBuffer blank;
                for (const ExrChannel& channel : part.channels)
                    blank.insert(channel.name, Imf::Slice::Make(exr_detail::pixelType(channel.type), zeros.data(), data, 4, 4 * size_t(part.width),
                                                                channel.sampling, channel.sampling));
                out.setFrameBuffer(blank);
                for (int ly = 0; ly < out.numYLevels(); ++ly)
                    for (int lx = 0; lx < out.numXLevels(); ++lx) {
                        if (lx == 0 && ly == 0) continue;
                        if (part.layout.levels == Imf::MIPMAP_LEVELS && lx != ly) continue;
                        out.writeTiles(0, out.numXTiles(lx) - 1, 0, out.numYTiles(ly) - 1, lx, ly);
                    }
            } else {
                Imf::OutputPart out(file, int(p));
                out.setFrameBuffer(exr_detail::frameBuffer(part, planes, data));
                out.writePixels(int(part.height));
            }
        }
    }
    const std::string bytes = stream.str();
    return std::vector<uint8_t>(bytes.begin(), bytes.end());
}

// One scanline or tiled part.
inline std::vector<uint8_t> makeExr(uint32_t width, uint32_t height, std::vector<ExrChannel> channels, ExrLayout layout = {}) {
    return makeExrParts({ExrPart{"", width, height, std::move(channels), layout, false}});
}

// R, G, B (and A = 1) planes from interleaved RGB texels.
inline std::vector<ExrChannel> rgbChannels(const std::vector<float>& rgb, ExrType type, bool alpha = false) {
    std::vector<ExrChannel> channels = {{"R", type, {}}, {"G", type, {}}, {"B", type, {}}};
    for (size_t i = 0; i < rgb.size(); ++i) channels[i % 3].values.push_back(rgb[i]);
    if (alpha) channels.push_back({"A", type, std::vector<float>(rgb.size() / 3, 1.0f)});
    return channels;
}

// Every compression OpenEXR 3.1 writes, for scanline images (B44/B44A and DWA are lossy on HALF;
// B44 leaves FLOAT channels uncompressed).
inline constexpr Imf::Compression kExrCompressions[] = {
    Imf::NO_COMPRESSION,  Imf::RLE_COMPRESSION,   Imf::ZIPS_COMPRESSION, Imf::ZIP_COMPRESSION,  Imf::PIZ_COMPRESSION,
    Imf::PXR24_COMPRESSION, Imf::B44_COMPRESSION, Imf::B44A_COMPRESSION, Imf::DWAA_COMPRESSION, Imf::DWAB_COMPRESSION};

inline std::string compressionName(Imf::Compression compression) {
    static const char* names[] = {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"};
    return size_t(compression) < std::size(names) ? names[compression] : "unknown";
}

}  // namespace candela::test
