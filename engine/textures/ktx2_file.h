#pragma once
// KTX 2.0 files with Basis Universal payloads (KHR_texture_basisu), read by hand from the KTX 2.0
// specification: the header, the level index, the data format descriptor (DFD), the key/value data
// and the supercompression global data are checked against the file before anything is decoded;
// ETC1S (BasisLZ) and UASTC (none or Zstandard supercompression) levels are decoded to RGBA8 by
// basis_etc1s.h and basis_uastc.h. Errors are candela::UserError with one line starting "KTX2: ".
// docs/textures.md says what is supported and how it is tested.

#include "textures/decoded_texture.h"

#include <cstdint>
#include <span>
#include <string>

namespace candela::textures {

enum class BasisPayload : uint8_t { Etc1s, Uastc };

// The supercompression schemes of the KTX 2.0 specification's table; KHR_texture_basisu allows
// BasisLz with ETC1S and None or Zstandard with UASTC.
enum class Supercompression : uint32_t { None = 0, BasisLz = 1, Zstandard = 2, Zlib = 3 };

// What a KTX2 file's header, DFD and key/value data say, once checked.
struct Ktx2Info {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t levelCount = 1;  // levels stored in the file (a levelCount of 0 in the header reads as 1)
    BasisPayload payload = BasisPayload::Uastc;
    Supercompression supercompression = Supercompression::None;
    bool alpha = false;        // the DFD names an alpha channel (ETC1S_AAA, UASTC_RGBA)
    bool srgb = false;         // the DFD's transfer function is sRGB
    std::string orientation;   // KTXorientation's value, empty when absent
    std::string writer;        // KTXwriter's value, empty when absent
    uint64_t payloadBytes = 0; // the sum of the levels' byteLength plus the global data (what the file stores)
};

// True when `bytes` starts with the KTX 2.0 file identifier («KTX 20»\r\n\x1A\n).
bool isKtx2(std::span<const uint8_t> bytes);

// Reads and checks everything but the payload: the identifier, header fields (a 2D texture, one
// face, no layers, vkFormat UNDEFINED, a supercompression scheme its payload allows), dimensions
// (≥ 1 and ≤ `maxDimension` per side), the level count against the dimensions, every level's and
// section's offset and length against the file, the level index's sizes against the payload's
// block count, the DFD's structure and colour model, and the key/value data's structure.
// Throws UserError("KTX2: …").
Ktx2Info readKtx2Info(std::span<const uint8_t> bytes, uint32_t maxDimension);

// readKtx2Info, then decodes every level stored to RGBA8 (level 0 first). Zstandard levels are
// inflated into buffers of the size the level index declares (checked against the block count
// before any allocation). KTXorientation "ru" (rows bottom first) is flipped, with a note; a width
// or height that is not a multiple of 4, or a KTXswizzle other than rgba, is a warning.
// Throws UserError("KTX2: …") naming the level for a payload that does not decode.
DecodedTexture decodeKtx2(std::span<const uint8_t> bytes, uint32_t maxDimension);

}  // namespace candela::textures
