#include "assets/stb_image_decoder.h"

#include "core/process_memory.h"

#include <cstdlib>

namespace {

// Buffers of at least half a huge page (a 2048² JPEG's chroma planes are 1 MiB) take whole huge
// pages (core/process_memory.h allocateInHugePages).
constexpr size_t kHugePage = size_t(2) << 20;

void* decoderMalloc(size_t bytes) { return bytes < kHugePage / 2 ? std::malloc(bytes) : candela::allocateInHugePages(bytes); }

void* decoderRealloc(void* data, size_t bytes) {
    void* grown = std::realloc(data, bytes);
    if (grown && bytes >= kHugePage) candela::adviseHugePages(grown, bytes);
    return grown;
}

}  // namespace

#define STBI_MALLOC(bytes) decoderMalloc(bytes)
#define STBI_REALLOC(data, bytes) decoderRealloc(data, bytes)
#define STBI_FREE(data) std::free(data)
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

namespace candela::assets::stb {

void PixelsFree::operator()(void* pixels) const { stbi_image_free(pixels); }

bool info(std::span<const uint8_t> bytes, int& width, int& height, int& channels) {
    return stbi_info_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels) != 0;
}

bool is16Bit(std::span<const uint8_t> bytes) { return stbi_is_16_bit_from_memory(bytes.data(), int(bytes.size())) != 0; }

Pixels<uint8_t> loadRgba8(std::span<const uint8_t> bytes, int& width, int& height) {
    int channels = 0;
    return Pixels<uint8_t>(stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4));
}

Pixels<uint16_t> loadRgba16(std::span<const uint8_t> bytes, int& width, int& height) {
    int channels = 0;
    return Pixels<uint16_t>(stbi_load_16_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4));
}

const char* failureReason() { return stbi_failure_reason(); }

}  // namespace candela::assets::stb
