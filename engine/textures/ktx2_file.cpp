#include "textures/ktx2_file.h"

#include "core/errors.h"
#include "textures/basis_etc1s.h"
#include "textures/basis_uastc.h"

#include <zstd.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

namespace candela::textures {
namespace {

constexpr uint8_t kIdentifier[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
constexpr size_t kHeaderBytes = 80;
constexpr size_t kLevelEntryBytes = 24;

// The Khronos Data Format Specification's values a Basis Universal DFD uses.
constexpr uint32_t kModelEtc1s = 163;
constexpr uint32_t kModelUastc = 166;
constexpr uint32_t kTransferLinear = 1;
constexpr uint32_t kTransferSrgb = 2;
constexpr uint32_t kChannelEtc1sRgb = 0, kChannelEtc1sAaa = 15;
constexpr uint32_t kChannelUastcRgb = 0, kChannelUastcRgba = 3;
constexpr uint32_t kFlagPremultiplied = 1;

[[noreturn]] void failKtx2(const std::string& problem) { throw UserError("KTX2: " + problem); }

uint32_t u32(std::span<const uint8_t> bytes, size_t at) {
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;  // little-endian hosts only (x86-64, AArch64), as the rest of Candela
}

uint64_t u64(std::span<const uint8_t> bytes, size_t at) {
    uint64_t v = 0;
    std::memcpy(&v, bytes.data() + at, 8);
    return v;
}

// `length` bytes at `offset` lie inside a file of `size` bytes.
bool inside(uint64_t offset, uint64_t length, uint64_t size) { return offset <= size && length <= size - offset; }

std::string levelName(uint32_t level) { return "level " + std::to_string(level); }

uint32_t levelSize(uint32_t size, uint32_t level) { return std::max(1u, size >> level); }

uint64_t blockBytes(uint32_t width, uint32_t height) {
    return uint64_t((width + 3) / 4) * ((height + 3) / 4) * 16;
}

struct LevelEntry {
    uint64_t offset = 0;
    uint64_t length = 0;
    uint64_t uncompressedLength = 0;
};

// The parts of a checked file the decoder needs besides Ktx2Info.
struct Layout {
    Ktx2Info info;
    std::vector<LevelEntry> levels;  // level 0 first
    std::span<const uint8_t> globalData;
    std::string swizzle;
    bool premultiplied = false;
};

// Reads the basic data format descriptor block: colour model, transfer function and the channels.
void readDfd(std::span<const uint8_t> file, uint32_t offset, uint32_t length, Layout& layout) {
    if (length < 4 + 24) failKtx2("data format descriptor of " + std::to_string(length) + " bytes is too short");
    const std::span<const uint8_t> dfd = file.subspan(offset, length);
    if (u32(dfd, 0) != length)
        failKtx2("data format descriptor says " + std::to_string(u32(dfd, 0)) + " bytes, the header " + std::to_string(length));
    const uint32_t word0 = u32(dfd, 4), word1 = u32(dfd, 8), word2 = u32(dfd, 12);
    const uint32_t vendor = word0 & 0x1FFFF, type = word0 >> 17;
    const uint32_t blockSize = word1 >> 16;
    if (vendor != 0 || type != 0) failKtx2("the first data format descriptor block is not Khronos's basic block");
    if (blockSize < 24 || blockSize > length - 4 || (blockSize - 24) % 16 != 0)
        failKtx2("data format descriptor block size " + std::to_string(blockSize) + " does not fit");
    const uint32_t model = word2 & 0xFF, transfer = (word2 >> 16) & 0xFF, flags = word2 >> 24;
    if (model == kModelEtc1s) layout.info.payload = BasisPayload::Etc1s;
    else if (model == kModelUastc) layout.info.payload = BasisPayload::Uastc;
    else failKtx2("colour model " + std::to_string(model) + " is not Basis Universal's ETC1S (163) or UASTC (166)");
    if (transfer != kTransferLinear && transfer != kTransferSrgb)
        failKtx2("transfer function " + std::to_string(transfer) + " is neither linear (1) nor sRGB (2)");
    layout.info.srgb = transfer == kTransferSrgb;
    layout.premultiplied = (flags & kFlagPremultiplied) != 0;
    const uint32_t samples = (blockSize - 24) / 16;
    const bool etc1s = layout.info.payload == BasisPayload::Etc1s;
    if (samples < 1 || samples > (etc1s ? 2u : 1u))
        failKtx2(std::to_string(samples) + " DFD samples for " + (etc1s ? "ETC1S (1 or 2 allowed)" : "UASTC (1 allowed)"));
    for (uint32_t s = 0; s < samples; ++s) {
        const uint32_t channel = (u32(dfd, 4 + 24 + 16 * s) >> 24) & 0x0F;
        if (etc1s && s == 0 && channel != kChannelEtc1sRgb) failKtx2("ETC1S's first channel is not RGB");
        if (etc1s && s == 1 && channel != kChannelEtc1sAaa) failKtx2("ETC1S's second channel is not AAA");
        if (!etc1s && channel != kChannelUastcRgb && channel != kChannelUastcRgba)
            failKtx2("UASTC channel " + std::to_string(channel) + " is neither RGB nor RGBA");
        if ((etc1s && s == 1) || (!etc1s && channel == kChannelUastcRgba)) layout.info.alpha = true;
    }
}

// Walks the key/value data: every entry's length inside the section, keys NUL-terminated UTF-8.
void readKeyValues(std::span<const uint8_t> file, uint32_t offset, uint32_t length, Layout& layout) {
    const std::span<const uint8_t> kvd = file.subspan(offset, length);
    size_t at = 0;
    while (at < kvd.size()) {
        if (kvd.size() - at < 4) failKtx2("key/value data ends inside an entry's length");
        const uint32_t entry = u32(kvd, at);
        at += 4;
        if (entry > kvd.size() - at) failKtx2("key/value entry of " + std::to_string(entry) + " bytes runs past its section");
        const std::string_view text(reinterpret_cast<const char*>(kvd.data() + at), entry);
        const size_t nul = text.find('\0');
        if (nul == std::string_view::npos || nul == 0) failKtx2("key/value entry without a NUL-terminated key");
        const std::string_view key = text.substr(0, nul);
        std::string_view value = text.substr(nul + 1);
        if (!value.empty() && value.back() == '\0') value.remove_suffix(1);
        if (key == "KTXorientation") layout.info.orientation = std::string(value.substr(0, 8));
        else if (key == "KTXswizzle") layout.swizzle = std::string(value.substr(0, 8));
        else if (key == "KTXwriter") layout.info.writer = std::string(value.substr(0, 120));
        at += (entry + 3) & ~size_t(3);  // values are padded to 4 bytes
    }
}

Layout readLayout(std::span<const uint8_t> file, uint32_t maxDimension) {
    if (file.size() < kHeaderBytes)
        failKtx2("truncated: " + std::to_string(file.size()) + " bytes, the header needs " + std::to_string(kHeaderBytes));
    if (!isKtx2(file)) failKtx2("not a KTX 2.0 file (wrong identifier)");
    Layout layout;
    Ktx2Info& info = layout.info;
    const uint32_t vkFormat = u32(file, 12), width = u32(file, 20), height = u32(file, 24), depth = u32(file, 28);
    const uint32_t layers = u32(file, 32), faces = u32(file, 36), levelCount = u32(file, 40), scheme = u32(file, 44);
    if (vkFormat != 0)
        failKtx2("vkFormat " + std::to_string(vkFormat) + " is not a Basis Universal payload (KHR_texture_basisu needs VK_FORMAT_UNDEFINED)");
    if (width == 0 || height == 0) failKtx2("size " + std::to_string(width) + "x" + std::to_string(height) + " is not a 2D image");
    if (width > maxDimension || height > maxDimension)
        failKtx2("image size " + std::to_string(width) + "x" + std::to_string(height) + " exceeds the limit of " +
             std::to_string(maxDimension) + " pixels per side");
    if (depth != 0) failKtx2("a 3D texture (pixelDepth " + std::to_string(depth) + "), glTF textures are 2D");
    if (layers > 1) failKtx2("an array of " + std::to_string(layers) + " layers, glTF textures are single images");
    if (faces != 1) failKtx2(std::to_string(faces) + " faces, glTF textures have one");
    const uint32_t fullChain = uint32_t(std::bit_width(std::max(width, height)));
    if (levelCount > fullChain)
        failKtx2(std::to_string(levelCount) + " mip levels, a " + std::to_string(width) + "x" + std::to_string(height) +
             " image has at most " + std::to_string(fullChain));
    info.width = width;
    info.height = height;
    info.levelCount = std::max(levelCount, 1u);
    if (scheme > 3) failKtx2("unknown supercompression scheme " + std::to_string(scheme));
    info.supercompression = Supercompression(scheme);

    const uint64_t indexEnd = kHeaderBytes + uint64_t(info.levelCount) * kLevelEntryBytes;
    if (indexEnd > file.size()) failKtx2("truncated: the level index needs " + std::to_string(indexEnd) + " bytes");
    const uint32_t dfdOffset = u32(file, 48), dfdLength = u32(file, 52);
    const uint32_t kvdOffset = u32(file, 56), kvdLength = u32(file, 60);
    const uint64_t sgdOffset = u64(file, 64), sgdLength = u64(file, 72);
    if (!inside(dfdOffset, dfdLength, file.size()) || dfdOffset < indexEnd)
        failKtx2("data format descriptor (" + std::to_string(dfdLength) + " bytes at " + std::to_string(dfdOffset) + ") lies outside the file");
    if (!inside(kvdOffset, kvdLength, file.size()) || (kvdLength > 0 && kvdOffset < indexEnd))
        failKtx2("key/value data (" + std::to_string(kvdLength) + " bytes at " + std::to_string(kvdOffset) + ") lies outside the file");
    if (!inside(sgdOffset, sgdLength, file.size()) || (sgdLength > 0 && sgdOffset < indexEnd))
        failKtx2("supercompression global data (" + std::to_string(sgdLength) + " bytes at " + std::to_string(sgdOffset) +
             ") lies outside the file");
    readDfd(file, dfdOffset, dfdLength, layout);
    readKeyValues(file, kvdOffset, kvdLength, layout);

    const bool etc1s = info.payload == BasisPayload::Etc1s;
    if (etc1s && info.supercompression != Supercompression::BasisLz)
        failKtx2("ETC1S payload with supercompression scheme " + std::to_string(scheme) + " (BasisLZ, 1, is required)");
    if (!etc1s && info.supercompression != Supercompression::None && info.supercompression != Supercompression::Zstandard)
        failKtx2("UASTC payload with supercompression scheme " + std::to_string(scheme) + " (none or Zstandard allowed)");
    if (etc1s != (sgdLength > 0)) failKtx2(etc1s ? "BasisLZ without global data" : "global data without BasisLZ");
    layout.globalData = file.subspan(size_t(sgdOffset), size_t(sgdLength));
    info.payloadBytes = sgdLength;

    for (uint32_t level = 0; level < info.levelCount; ++level) {
        const size_t at = kHeaderBytes + level * kLevelEntryBytes;
        LevelEntry entry{u64(file, at), u64(file, at + 8), u64(file, at + 16)};
        if (!inside(entry.offset, entry.length, file.size()) || entry.offset < indexEnd)
            failKtx2(levelName(level) + " (" + std::to_string(entry.length) + " bytes at " + std::to_string(entry.offset) +
                 ") lies outside the file");
        const uint64_t blocks = blockBytes(levelSize(width, level), levelSize(height, level));
        if (info.supercompression == Supercompression::None && (entry.length != blocks || entry.uncompressedLength != blocks))
            failKtx2(levelName(level) + " holds " + std::to_string(entry.length) + " bytes, its UASTC blocks need " +
                 std::to_string(blocks));
        if (info.supercompression == Supercompression::Zstandard && entry.uncompressedLength != blocks)
            failKtx2(levelName(level) + " inflates to " + std::to_string(entry.uncompressedLength) + " bytes, its UASTC blocks need " +
                 std::to_string(blocks));
        if (entry.length == 0) failKtx2(levelName(level) + " is empty");
        info.payloadBytes += entry.length;
        layout.levels.push_back(entry);
    }
    return layout;
}

// Zstandard-inflates one level into exactly `expected` bytes.
std::vector<uint8_t> inflate(std::span<const uint8_t> compressed, uint64_t expected, uint32_t level) {
    const unsigned long long declared = ZSTD_getFrameContentSize(compressed.data(), compressed.size());
    if (declared == ZSTD_CONTENTSIZE_ERROR) failKtx2(levelName(level) + ": not a Zstandard frame");
    if (declared != ZSTD_CONTENTSIZE_UNKNOWN && declared != expected)
        failKtx2(levelName(level) + ": Zstandard frame holds " + std::to_string(declared) + " bytes, the level index says " +
             std::to_string(expected));
    std::vector<uint8_t> out(static_cast<size_t>(expected));
    const size_t got = ZSTD_decompress(out.data(), out.size(), compressed.data(), compressed.size());
    if (ZSTD_isError(got)) failKtx2(levelName(level) + ": Zstandard: " + ZSTD_getErrorName(got));
    if (got != expected)
        failKtx2(levelName(level) + ": Zstandard gave " + std::to_string(got) + " bytes, the level index says " + std::to_string(expected));
    return out;
}

}  // namespace

bool isKtx2(std::span<const uint8_t> bytes) {
    return bytes.size() >= sizeof(kIdentifier) && std::memcmp(bytes.data(), kIdentifier, sizeof(kIdentifier)) == 0;
}

Ktx2Info readKtx2Info(std::span<const uint8_t> bytes, uint32_t maxDimension) { return readLayout(bytes, maxDimension).info; }

DecodedTexture decodeKtx2(std::span<const uint8_t> bytes, uint32_t maxDimension) {
    const Layout layout = readLayout(bytes, maxDimension);
    const Ktx2Info& info = layout.info;
    DecodedTexture out;
    const bool flip = info.orientation.size() >= 2 && info.orientation[1] == 'u';
    if (!info.orientation.empty() && info.orientation != "rd" && info.orientation != "ru")
        out.report.warnings.push_back("KTXorientation '" + info.orientation + "' is not 'rd' as KHR_texture_basisu requires (drawn as stored)");
    if (flip) out.report.notes.push_back("KTXorientation 'ru' (rows bottom first): flipped to glTF's top-first rows");
    if (!layout.swizzle.empty() && layout.swizzle != "rgba")
        out.report.warnings.push_back("KTXswizzle '" + layout.swizzle + "' is not 'rgba' as KHR_texture_basisu requires (ignored)");
    if (info.width % 4 != 0 || info.height % 4 != 0)
        out.report.warnings.push_back("size " + std::to_string(info.width) + "x" + std::to_string(info.height) +
                               " is not a multiple of 4 as KHR_texture_basisu requires (decoded anyway)");
    if (layout.premultiplied) out.report.warnings.push_back("the DFD marks alpha premultiplied, glTF's is straight (drawn as straight)");

    std::optional<BasisLzGlobal> global;
    if (info.payload == BasisPayload::Etc1s) {
        global.emplace(BasisLzGlobal::parse(layout.globalData, info.levelCount));
        const bool alphaSlices = global->imageDesc(0).alphaSliceByteLength > 0;
        if (alphaSlices != info.alpha)
            failKtx2(std::string("the DFD ") + (info.alpha ? "names" : "has no") + " an alpha channel but the images " +
                 (alphaSlices ? "have" : "have no") + " alpha slices");
    }
    for (uint32_t level = 0; level < info.levelCount; ++level) {
        const LevelEntry& entry = layout.levels[level];
        TextureLevel decoded;
        decoded.width = levelSize(info.width, level);
        decoded.height = levelSize(info.height, level);
        decoded.rgba8.resize(size_t(decoded.width) * decoded.height * 4);
        const std::span<const uint8_t> stored = bytes.subspan(size_t(entry.offset), size_t(entry.length));
        try {
            if (info.payload == BasisPayload::Etc1s) {
                global->decode(level, stored, decoded.width, decoded.height, decoded.rgba8);
            } else if (info.supercompression == Supercompression::Zstandard) {
                const std::vector<uint8_t> blocks = inflate(stored, entry.uncompressedLength, level);
                decodeUastcImage(blocks, decoded.width, decoded.height, info.srgb, decoded.rgba8);
            } else {
                decodeUastcImage(stored, decoded.width, decoded.height, info.srgb, decoded.rgba8);
            }
        } catch (const UserError& e) {
            const std::string message = e.what();
            if (message.rfind("KTX2: ", 0) == 0) throw;
            failKtx2(levelName(level) + ": " + message);
        }
        if (flip) {
            const size_t row = size_t(decoded.width) * 4;
            for (uint32_t y = 0; y < decoded.height / 2; ++y)
                std::swap_ranges(decoded.rgba8.begin() + ptrdiff_t(y * row), decoded.rgba8.begin() + ptrdiff_t((y + 1) * row),
                                 decoded.rgba8.begin() + ptrdiff_t((decoded.height - 1 - y) * row));
        }
        out.levels.push_back(std::move(decoded));
    }
    return out;
}

}  // namespace candela::textures
