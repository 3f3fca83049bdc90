#include "textures/basis_etc1s.h"

#include "core/errors.h"
#include "textures/basis_etc1s_huffman.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <vector>

// Section names below are the KTX 2.0 specification's: "BasisLZ Global Data" (the layout parsed by
// BasisLzGlobal::parse) and the appendix "BasisLZ/ETC1S Bitstream Specification" (the codebooks,
// the slice Huffman tables and "ETC1S Slice Decoding").

namespace candela::textures {
namespace {

using etc1s::BitReader;
using etc1s::HuffmanTable;
using etc1s::StreamError;

constexpr uint32_t kGlobalHeaderBytes = 20;     // endpointCount .. extendedByteLength
constexpr uint32_t kImageDescBytes = 20;  // five UInt32
constexpr uint32_t kPFrameFlag = 0x02;    // ImageDesc.imageFlags isPFrame

// "ETC1S Slice Block Decoding" constants.
constexpr uint32_t kEndpointPredRepeatSymbol = 4 * 4 * 4 * 4;  // ENDPOINT_PRED_REPEAT_LAST_SYMBOL
constexpr uint32_t kEndpointPredMinRepeat = 3;                 // ENDPOINT_PRED_MIN_REPEAT_COUNT
constexpr uint32_t kSelectorRunThreshold = 3;                  // SELECTOR_HISTORY_BUF_RLE_COUNT_THRESH
constexpr uint32_t kSelectorRunLongSymbol = (1u << 6) - 1;     // SELECTOR_HISTORY_BUF_RLE_COUNT_TOTAL - 1

// ETC1 intensity modifier tables (Khronos Data Format Specification, ETC1 chapter, "Intensity
// modifier sets for ETC1 blocks"), each row in ETC1S selector order: selector 0 = -b, 1 = -a,
// 2 = +a, 3 = +b ("ETC1S Selector Codebooks").
constexpr std::array<std::array<int, 4>, 8> kIntensityModifiers = {{{-8, -2, 2, 8},
                                                                     {-17, -5, 5, 17},
                                                                     {-29, -9, 9, 29},
                                                                     {-42, -13, 13, 42},
                                                                     {-60, -18, 18, 60},
                                                                     {-80, -24, 24, 80},
                                                                     {-106, -33, 33, 106},
                                                                     {-183, -47, 47, 183}}};

// Little-endian fields, as every KTX2 field is.
uint16_t readU16(const uint8_t* p) { return uint16_t(p[0] | p[1] << 8); }
uint32_t readU32(const uint8_t* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

[[noreturn]] void failGlobal(const std::string& problem) { throw UserError("BasisLZ global data: " + problem); }

// The four texel colours (RGBA, alpha 255) one ETC1S endpoint gives its block.
using BlockColors = std::array<std::array<uint8_t, 4>, 4>;

// An ETC1S endpoint is an ETC1 block in differential mode with a zero delta and one intensity
// table for both subblocks (KDFS ETC1 chapter): the 5-bit base colour is widened to 8 bits by
// repeating its top bits, and each selector adds its modifier to all three channels, clamped.
BlockColors blockColors(const std::array<uint8_t, 3>& color5, uint32_t intensity) {
    BlockColors colors{};
    for (uint32_t s = 0; s < 4; ++s) {
        for (uint32_t c = 0; c < 3; ++c) {
            const int base = color5[c] << 3 | color5[c] >> 2;
            colors[s][c] = uint8_t(std::clamp(base + kIntensityModifiers[intensity][s], 0, 255));
        }
        colors[s][3] = 255;
    }
    return colors;
}

}  // namespace

namespace etc1s {

// What the slices of every image share: the decoded codebooks and the slice Huffman tables.
struct Codebooks {
    std::vector<BlockColors> endpoints;             // endpointCount entries
    std::vector<std::array<uint8_t, 4>> selectors;  // selectorCount entries: a byte per row, texel x in bits 2x..2x+1
    // "ETC1S Slice Huffman Tables"
    HuffmanTable endpointPredModel;
    HuffmanTable endpointDeltaModel;
    HuffmanTable selectorModel;
    HuffmanTable selectorHistoryBufRleModel;
    uint32_t selectorHistoryBufSize = 0;
};

}  // namespace etc1s

struct BasisLzGlobal::Data : etc1s::Codebooks {
    std::vector<BasisLzImageDesc> images;
};

namespace {

// "ETC1S Endpoint Codebooks": four Huffman tables, a grayscale flag, then DPCM-coded intensity table
// indices and 5-bit colours; the colour delta table is chosen by the previous value's range.
std::vector<BlockColors> readEndpoints(std::span<const uint8_t> bytes, uint32_t count) {
    BitReader reader(bytes);
    const std::array<HuffmanTable, 3> colorDeltaModels = {reader.huffmanTable(), reader.huffmanTable(),
                                                          reader.huffmanTable()};
    const HuffmanTable intenDeltaModel = reader.huffmanTable();
    for (uint32_t i = 0; i < 3; ++i)
        if (!colorDeltaModels[i].symbolCount())
            throw StreamError("colour delta table " + std::to_string(i) + " is empty");
    if (!intenDeltaModel.symbolCount()) throw StreamError("intensity delta table is empty");
    const bool grayscale = reader.bits(1) != 0;

    std::vector<BlockColors> endpoints(count);
    std::array<uint8_t, 3> color{16, 16, 16};
    uint32_t intensity = 0;
    for (BlockColors& endpoint : endpoints) {
        intensity = (intensity + reader.huffman(intenDeltaModel)) & 7;
        for (uint32_t c = 0; c < (grayscale ? 1u : 3u); ++c) {
            const uint32_t model = color[c] <= 9 ? 0 : color[c] <= 21 ? 1 : 2;  // [0..9], [10..21], [22..31]
            color[c] = uint8_t((color[c] + reader.huffman(colorDeltaModels[model])) & 31);
        }
        if (grayscale) color[1] = color[2] = color[0];
        endpoint = blockColors(color, intensity);
    }
    return endpoints;
}

// "ETC1S Selector Codebooks": two reserved zero bits, then raw selectors or a first raw selector and
// Huffman-coded XOR deltas of each row byte against the previous selector's.
std::vector<std::array<uint8_t, 4>> readSelectors(std::span<const uint8_t> bytes, uint32_t count) {
    BitReader reader(bytes);
    if (reader.bits(2) != 0) throw StreamError("reserved bits set (a global or hybrid selector codebook)");
    const bool raw = reader.bits(1) != 0;
    std::vector<std::array<uint8_t, 4>> selectors(count);
    if (raw) {
        for (auto& selector : selectors)
            for (uint8_t& row : selector) row = uint8_t(reader.bits(8));
        return selectors;
    }
    const HuffmanTable deltaSelectorModel = reader.huffmanTable();
    if (count > 1 && !deltaSelectorModel.symbolCount()) throw StreamError("delta table is empty");
    for (uint8_t& row : selectors[0]) row = uint8_t(reader.bits(8));
    for (uint32_t i = 1; i < count; ++i) {
        for (uint32_t j = 0; j < 4; ++j) {
            const uint32_t delta = reader.huffman(deltaSelectorModel);
            if (delta > 255) throw StreamError("row delta " + std::to_string(delta) + " is not a byte");
            selectors[i][j] = uint8_t(selectors[i - 1][j] ^ delta);
        }
    }
    return selectors;
}

// The approximate move-to-front selector history ("ETC1S Approximate Move to Front Routines").
class SelectorHistory {
public:
    explicit SelectorHistory(uint32_t size) : mValues(size, 0), mRover(size / 2) {}
    uint32_t size() const { return uint32_t(mValues.size()); }
    uint32_t operator[](uint32_t index) const { return mValues[index]; }
    void add(uint32_t value) {
        mValues[mRover++] = value;
        if (mRover == mValues.size()) mRover = uint32_t(mValues.size() / 2);
    }
    void use(uint32_t index) {
        if (index) std::swap(mValues[index / 2], mValues[index]);
    }

private:
    std::vector<uint32_t> mValues;
    uint32_t mRover;
};

// "ETC1S Slice Block Decoding" for an I-frame: walks the blocksX × blocksY blocks in raster order and
// calls block(x, y, colours, selector) with the codebook entries each block's (checked) indices name.
// Every loop is bounded by the block count, so no input can make it run longer than the image needs.
template <class BlockFn>
void decodeSlice(const etc1s::Codebooks& global, std::span<const uint8_t> slice, uint32_t blocksX, uint32_t blocksY,
                 BlockFn&& block) {
    BitReader reader(slice);
    const uint32_t endpointCount = uint32_t(global.endpoints.size());
    const uint32_t selectorCount = uint32_t(global.selectors.size());
    const uint64_t totalBlocks = uint64_t(blocksX) * blocksY;
    // Selector symbols: [0, selectorCount) codebook indices, then the history buffer's entries, then the run symbol.
    const uint32_t historyRunSymbol = selectorCount + global.selectorHistoryBufSize;

    // Endpoint indices of the previous and the current row of blocks (left/upper/upper-left prediction).
    std::vector<uint16_t> upperEndpoints(blocksX), rowEndpoints(blocksX);
    // An even row's predictor symbols keep their top 4 bits for the two blocks below them.
    std::vector<uint8_t> oddRowPredBits((blocksX + 1) / 2);
    SelectorHistory history(global.selectorHistoryBufSize);

    uint32_t predBits = 0;
    uint32_t prevPredSymbol = 0;
    uint64_t predRepeat = 0;
    uint32_t prevEndpoint = 0;
    uint64_t selectorRun = 0;

    for (uint32_t y = 0; y < blocksY; ++y) {
        for (uint32_t x = 0; x < blocksX; ++x) {
            // One predictor symbol per 2x2 blocks, 2 bits per block in raster order, run-length coded.
            if ((x & 1) == 0) {
                if ((y & 1) == 0) {
                    if (predRepeat) {
                        --predRepeat;
                        predBits = prevPredSymbol;
                    } else {
                        const uint32_t symbol = reader.huffman(global.endpointPredModel);
                        if (symbol == kEndpointPredRepeatSymbol) {  // the previous symbol, 3 or more times in all
                            predRepeat = uint64_t(reader.vlc(4)) + kEndpointPredMinRepeat - 1;
                            predBits = prevPredSymbol;
                        } else if (symbol > kEndpointPredRepeatSymbol) {
                            throw StreamError("endpoint predictor symbol " + std::to_string(symbol) + " out of range");
                        } else {
                            predBits = prevPredSymbol = symbol;
                        }
                    }
                    oddRowPredBits[x / 2] = uint8_t(predBits >> 4);
                } else {
                    predBits = oddRowPredBits[x / 2];
                }
            }
            const uint32_t pred = predBits & 3;
            predBits >>= 2;

            uint32_t endpoint = 0;
            switch (pred) {
                case 0:  // the left block's endpoint
                    if (x == 0) throw StreamError("left endpoint prediction in the first column");
                    endpoint = prevEndpoint;
                    break;
                case 1:  // the upper block's
                    if (y == 0) throw StreamError("upper endpoint prediction in the first row");
                    endpoint = upperEndpoints[x];
                    break;
                case 2:  // the upper-left block's (in an I-frame)
                    if (x == 0 || y == 0)
                        throw StreamError("upper-left endpoint prediction on the first row or column");
                    endpoint = upperEndpoints[x - 1];
                    break;
                default:  // a Huffman-coded delta from the previous endpoint index, wrapping once
                    endpoint = reader.huffman(global.endpointDeltaModel) + prevEndpoint;
                    if (endpoint >= endpointCount) endpoint -= endpointCount;
                    if (endpoint >= endpointCount)
                        throw StreamError("endpoint index " + std::to_string(endpoint) + " out of range");
                    break;
            }
            rowEndpoints[x] = uint16_t(endpoint);
            prevEndpoint = endpoint;

            // The selector: a codebook index (which joins the history buffer), an entry of the history
            // buffer (which moves halfway to its front), or a run of blocks that all use history entry 0.
            uint32_t symbol = selectorCount;
            if (selectorRun) {
                --selectorRun;
            } else {
                symbol = reader.huffman(global.selectorModel);
                if (symbol == historyRunSymbol) {
                    const uint32_t runSymbol = reader.huffman(global.selectorHistoryBufRleModel);
                    selectorRun = (runSymbol == kSelectorRunLongSymbol ? uint64_t(reader.vlc(7)) : runSymbol) +
                                  kSelectorRunThreshold;
                    // A run longer than the slice is corrupt (Basis Universal's transcoder refuses it too).
                    if (selectorRun > totalBlocks)
                        throw StreamError("selector run of " + std::to_string(selectorRun) + " blocks");
                    --selectorRun;
                    symbol = selectorCount;
                }
            }
            uint32_t selector = symbol;
            if (symbol >= selectorCount) {
                const uint32_t entry = symbol - selectorCount;
                if (entry >= history.size())
                    throw StreamError("selector history entry " + std::to_string(entry) + " of " +
                                      std::to_string(history.size()));
                selector = history[entry];
                history.use(entry);
            } else if (history.size()) {
                history.add(selector);
            }
            block(x, y, global.endpoints[endpoint], global.selectors[selector]);
        }
        std::swap(upperEndpoints, rowEndpoints);
    }
}

void checkSlice(const std::string& image, const char* name, uint32_t offset, uint32_t length, size_t levelBytes) {
    if (uint64_t(offset) + length > levelBytes)
        throw UserError(image + name + " slice (bytes " + std::to_string(offset) + " + " + std::to_string(length) +
                        ") lies outside its level's " + std::to_string(levelBytes) + " bytes");
}

// The RGBA8 image being written; blocks on the right and bottom edges are clipped to it.
struct OutputImage {
    uint8_t* rgba;
    uint32_t width;
    uint32_t height;

    // The texels of block (x, y) that lie inside the image, and the address of its top-left texel.
    uint32_t columns(uint32_t x) const { return std::min(4u, width - x * 4); }
    uint32_t rows(uint32_t y) const { return std::min(4u, height - y * 4); }
    uint8_t* at(uint32_t x, uint32_t y) const { return rgba + (size_t(y) * 4 * width + size_t(x) * 4) * 4; }
};

// An RGB slice's block: RGB from the endpoint's colours, alpha 255.
void writeColorBlock(const OutputImage& image, uint32_t x, uint32_t y, const BlockColors& colors,
                     const std::array<uint8_t, 4>& selector) {
    const uint32_t columns = image.columns(x), rows = image.rows(y);
    uint8_t* out = image.at(x, y);
    for (uint32_t row = 0; row < rows; ++row, out += size_t(image.width) * 4)
        for (uint32_t column = 0; column < columns; ++column)
            std::memcpy(out + column * 4, colors[(selector[row] >> (column * 2)) & 3].data(), 4);
}

// An alpha slice's block: the decoded green channel becomes the alpha of the texels.
void writeAlphaBlock(const OutputImage& image, uint32_t x, uint32_t y, const BlockColors& colors,
                     const std::array<uint8_t, 4>& selector) {
    const uint32_t columns = image.columns(x), rows = image.rows(y);
    uint8_t* out = image.at(x, y) + 3;
    for (uint32_t row = 0; row < rows; ++row, out += size_t(image.width) * 4)
        for (uint32_t column = 0; column < columns; ++column)
            out[column * 4] = colors[(selector[row] >> (column * 2)) & 3][1];
}

}  // namespace

BasisLzGlobal::BasisLzGlobal(std::unique_ptr<Data> data) : mData(std::move(data)) {}
BasisLzGlobal::BasisLzGlobal(BasisLzGlobal&&) noexcept = default;
BasisLzGlobal& BasisLzGlobal::operator=(BasisLzGlobal&&) noexcept = default;
BasisLzGlobal::~BasisLzGlobal() = default;

uint32_t BasisLzGlobal::imageCount() const { return uint32_t(mData->images.size()); }

const BasisLzImageDesc& BasisLzGlobal::imageDesc(uint32_t index) const {
    if (index >= mData->images.size()) throw InternalError("BasisLzGlobal::imageDesc: index out of range");
    return mData->images[index];
}

BasisLzGlobal BasisLzGlobal::parse(std::span<const uint8_t> globalData, uint32_t imageCount) {
    if (globalData.size() < kGlobalHeaderBytes)
        failGlobal(std::to_string(globalData.size()) + " bytes, shorter than its " + std::to_string(kGlobalHeaderBytes) +
                   "-byte header");
    const uint8_t* p = globalData.data();
    const uint32_t endpointCount = readU16(p);
    const uint32_t selectorCount = readU16(p + 2);
    const uint32_t endpointsByteLength = readU32(p + 4);
    const uint32_t selectorsByteLength = readU32(p + 8);
    const uint32_t tablesByteLength = readU32(p + 12);
    const uint32_t extendedByteLength = readU32(p + 16);
    if (imageCount == 0) failGlobal("no images");
    if (endpointCount == 0) failGlobal("endpointCount is 0");
    if (selectorCount == 0) failGlobal("selectorCount is 0");
    if (extendedByteLength != 0)
        failGlobal("extendedByteLength is " + std::to_string(extendedByteLength) + " (ETC1S has no extended data)");
    // The section must be exactly the header, the image descriptions and the four byte arrays.
    const uint64_t expected = kGlobalHeaderBytes + uint64_t(kImageDescBytes) * imageCount + endpointsByteLength +
                              selectorsByteLength + tablesByteLength;
    if (expected != globalData.size())
        failGlobal(std::to_string(globalData.size()) + " bytes where its header and " + std::to_string(imageCount) +
                   " image descriptions add up to " + std::to_string(expected));

    auto data = std::make_unique<Data>();
    data->images.resize(imageCount);
    for (uint32_t i = 0; i < imageCount; ++i) {
        const uint8_t* d = p + kGlobalHeaderBytes + size_t(kImageDescBytes) * i;
        BasisLzImageDesc& desc = data->images[i];
        desc = {readU32(d), readU32(d + 4), readU32(d + 8), readU32(d + 12), readU32(d + 16)};
        const std::string name = "image " + std::to_string(i) + ": ";
        if (desc.rgbSliceByteLength == 0) failGlobal(name + "rgbSliceByteLength is 0");
        if (desc.alphaSliceByteLength == 0 && desc.alphaSliceByteOffset != 0)
            failGlobal(name + "an alpha slice offset without an alpha slice");
        if ((desc.alphaSliceByteLength != 0) != (data->images[0].alphaSliceByteLength != 0))
            failGlobal(name + "alpha slice presence differs from image 0");
    }

    const uint8_t* endpointsData = p + kGlobalHeaderBytes + size_t(kImageDescBytes) * imageCount;
    const uint8_t* selectorsData = endpointsData + endpointsByteLength;
    const uint8_t* tablesData = selectorsData + selectorsByteLength;
    const char* section = "endpoint codebook";
    try {
        data->endpoints = readEndpoints({endpointsData, endpointsByteLength}, endpointCount);
        section = "selector codebook";
        data->selectors = readSelectors({selectorsData, selectorsByteLength}, selectorCount);
        section = "slice Huffman tables";
        BitReader reader({tablesData, tablesByteLength});
        data->endpointPredModel = reader.huffmanTable();
        data->endpointDeltaModel = reader.huffmanTable();
        data->selectorModel = reader.huffmanTable();
        data->selectorHistoryBufRleModel = reader.huffmanTable();
        data->selectorHistoryBufSize = reader.bits(13);
        if (!data->endpointPredModel.symbolCount() || !data->endpointDeltaModel.symbolCount() ||
            !data->selectorModel.symbolCount() || !data->selectorHistoryBufRleModel.symbolCount())
            throw StreamError("a table is empty");
    } catch (const StreamError& e) {
        failGlobal(std::string(section) + ": " + e.what());
    }
    return BasisLzGlobal(std::move(data));
}

void BasisLzGlobal::decode(uint32_t index, std::span<const uint8_t> levelBytes, uint32_t width, uint32_t height,
                           std::span<uint8_t> rgba) const {
    if (index >= mData->images.size() || width == 0 || height == 0 || rgba.size() != uint64_t(width) * height * 4)
        throw InternalError("BasisLzGlobal::decode: arguments break its preconditions");
    const BasisLzImageDesc& desc = mData->images[index];
    const std::string name = "BasisLZ image " + std::to_string(index) + ": ";
    if (desc.imageFlags & kPFrameFlag) throw UserError(name + "a P-frame of an animation (not supported)");
    checkSlice(name, "RGB", desc.rgbSliceByteOffset, desc.rgbSliceByteLength, levelBytes.size());
    const bool alpha = desc.alphaSliceByteLength != 0;
    if (alpha) checkSlice(name, "alpha", desc.alphaSliceByteOffset, desc.alphaSliceByteLength, levelBytes.size());

    const uint32_t blocksX = (width + 3) / 4, blocksY = (height + 3) / 4;
    const OutputImage image{rgba.data(), width, height};
    const char* slice = "RGB slice";
    try {
        decodeSlice(*mData, levelBytes.subspan(desc.rgbSliceByteOffset, desc.rgbSliceByteLength), blocksX, blocksY,
                    [&](uint32_t x, uint32_t y, const BlockColors& colors, const std::array<uint8_t, 4>& selector) {
                        writeColorBlock(image, x, y, colors, selector);
                    });
        if (alpha) {
            // The alpha slice is an ETC1S image of its own, decoded with the same codebooks and tables.
            slice = "alpha slice";
            decodeSlice(*mData, levelBytes.subspan(desc.alphaSliceByteOffset, desc.alphaSliceByteLength), blocksX,
                        blocksY,
                        [&](uint32_t x, uint32_t y, const BlockColors& colors, const std::array<uint8_t, 4>& selector) {
                            writeAlphaBlock(image, x, y, colors, selector);
                        });
        }
    } catch (const StreamError& e) {
        throw UserError(name + slice + ": " + e.what());
    }
}

}  // namespace candela::textures
