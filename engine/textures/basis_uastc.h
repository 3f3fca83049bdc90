#pragma once
// UASTC LDR 4×4 (Basis Universal's UASTC format, a subset of ASTC 4×4 with its own 128-bit block
// coding) decoded to RGBA8 on the CPU: the payload of KHR_texture_basisu files whose data format
// descriptor's colour model is KHR_DF_MODEL_UASTC. Written from the UASTC specification; see
// docs/textures.md. No allocation, no Vulkan: the fuzz build links it.

#include <cstdint>
#include <span>

namespace candela::textures {

// Decodes one 16-byte UASTC block to 16 RGBA8 texels, row-major (texel (x, y) at
// texels[(y * 4 + x) * 4]), as the UASTC spec's "Decoding process" says: endpoints expanded to 16
// bits as (C << 8) | C, or (C << 8) | 0x80 when `srgb` (ASTC's sRGB decode mode; the data format
// descriptor's transfer function is sRGB), interpolated as ASTC does and cut to their top 8 bits:
// for R, G and B what a GPU decodes from the lossless UASTC → ASTC transcode (decode_unorm8, or the
// 8 bits its sRGB decode starts from). In sRGB mode the UASTC spec expands alpha like R, G and B, as
// Basis Universal's transcoder does, where ASTC bit-replicates it: a GPU's alpha may differ by 1
// there. Solid-colour blocks (mode 8) give their colour in both modes. Returns false, leaving
// `texels` unspecified, for the reserved mode 19 and for partition pattern indices past their table:
// the only invalid encodings (every other bit pattern decodes; trit and quint packs past 242 and 124
// decode digit by digit, as the spec asks). Never reads or writes outside the 16 and 64 bytes,
// whatever the block holds. Preconditions: `block` holds 16 bytes, `texels` 64.
bool decodeUastcBlock(const uint8_t* block, bool srgb, uint8_t* texels);

// Decodes a whole image: `blocks` holds ceil(width / 4) × ceil(height / 4) blocks of 16 bytes,
// row-major; `rgba` receives width × height × 4 bytes (texels of edge blocks past the image are
// dropped). Throws candela::UserError("UASTC block N at (x, y): invalid block") on the first
// invalid block, N its index and (x, y) its column and row in blocks. Preconditions (checked by the
// caller, asserted here): width, height ≥ 1, the two spans have exactly those sizes.
void decodeUastcImage(std::span<const uint8_t> blocks, uint32_t width, uint32_t height, bool srgb,
                      std::span<uint8_t> rgba);

}  // namespace candela::textures
