#pragma once
// BasisLZ/ETC1S (the KTX 2.0 specification's BasisLZ supercompression scheme, section "BasisLZ
// Global Data" and "ETC1S slice decoding") decoded to RGBA8 on the CPU: the payload of
// KHR_texture_basisu files with supercompressionScheme 1. Written from the KTX 2.0 specification
// and Basis Universal's ETC1S notes; see docs/textures.md. No Vulkan: the fuzz build links it.

#include <cstdint>
#include <memory>
#include <span>

namespace candela::textures {

// One entry of the global data's image descriptions: where an image's RGB slice and optional
// alpha slice lie in its level's bytes.
struct BasisLzImageDesc {
    uint32_t imageFlags = 0;  // ETC1S_P_FRAME = 0x02 (video P-frames: refused by decode)
    uint32_t rgbSliceByteOffset = 0;
    uint32_t rgbSliceByteLength = 0;
    uint32_t alphaSliceByteOffset = 0;
    uint32_t alphaSliceByteLength = 0;
};

// The decoded supercompression global data: endpoint and selector codebooks, the Huffman tables
// of the slices, the image descriptions. Parsing checks every length against `globalData` and
// every codebook entry; decoding checks every slice against its level.
class BasisLzGlobal {
public:
    // Parses the supercompression global data of a BasisLZ KTX2 file. `imageCount` is the number of
    // image descriptions the file must hold: the sum over mip levels of max(1, layerCount) ×
    // faceCount × max(1, pixelDepth >> level). Throws candela::UserError("BasisLZ global data: …")
    // on any inconsistency: a size other than the header's lengths add up to, codebook sizes of 0,
    // extended data (ETC1S has none), an empty RGB slice, an alpha slice in some images only, the
    // reserved selector-codebook bits set, Huffman tables that are no complete prefix code, a
    // codebook or table section ending early.
    static BasisLzGlobal parse(std::span<const uint8_t> globalData, uint32_t imageCount);

    BasisLzGlobal(BasisLzGlobal&&) noexcept;
    BasisLzGlobal& operator=(BasisLzGlobal&&) noexcept;
    ~BasisLzGlobal();

    uint32_t imageCount() const;
    const BasisLzImageDesc& imageDesc(uint32_t index) const;  // precondition: index < imageCount()

    // Decodes image `index` (its slices' offsets are relative to `levelBytes`, the bytes of the mip
    // level it belongs to, as the level index gives them) into `rgba` (width × height × 4 bytes,
    // row-major, rows in the slice's order). Alpha comes from the alpha slice's green channel when
    // the image has one, else 255. The result is bit for bit Basis Universal's transcode of the
    // slices to ETC1 (ETC1S blocks are ETC1 blocks in differential mode with a zero delta), decoded.
    // Throws candela::UserError("BasisLZ image N: …") for a P-frame (video: not supported), a slice
    // outside `levelBytes`, or a slice bit stream that is inconsistent (a prediction from outside
    // the image, a codebook index or history entry out of range, the stream ending early, …).
    // Preconditions (candela::InternalError otherwise): index < imageCount(); width, height ≥ 1;
    // rgba.size() == width × height × 4.
    void decode(uint32_t index, std::span<const uint8_t> levelBytes, uint32_t width, uint32_t height,
                std::span<uint8_t> rgba) const;

private:
    struct Data;
    explicit BasisLzGlobal(std::unique_ptr<Data> data);
    std::unique_ptr<Data> mData;
};

}  // namespace candela::textures
