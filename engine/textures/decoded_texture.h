#pragma once
// What the texture decoders of this folder produce: RGBA8 levels, level 0 first, and the notes a
// decoder has for the user (an animated WebP drawn from its first frame, a KTX2 orientation flipped).

#include "core/load_report.h"

#include <cstdint>
#include <string>
#include <vector>

namespace candela::textures {

struct TextureLevel {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba8;  // width × height × 4, top row first
};

struct DecodedTexture {
    // Level 0 and, for files that carry them (KTX2), the file's own smaller levels: each level's
    // size is the previous one's halved (⌊size / 2⌋, at least 1).
    std::vector<TextureLevel> levels;
    LoadReport report;  // its lines without the file's name (the caller adds it)
};

}  // namespace candela::textures
