#include "assets/stb_image_decoder.h"

#include "core/process_memory.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace {

// Every allocation stb_image makes starts 16 bytes into a block whose first 16 bytes say how many
// bytes were asked and where the block came from: the C heap, or for buffers of at least half a
// huge page (a 2048² JPEG's chroma planes are 1 MiB) whole huge pages mapped on their own
// (core/process_memory.h allocateInHugePages), given back to the system when freed.
constexpr size_t kHugePage = size_t(2) << 20;
struct Prefix {
    size_t bytes;
    size_t hugePages;
};
static_assert(sizeof(Prefix) == 16);

void* decoderMalloc(size_t bytes) {
    const bool huge = bytes >= kHugePage / 2;
    void* block = huge ? candela::allocateInHugePages(bytes + sizeof(Prefix)) : std::malloc(bytes + sizeof(Prefix));
    if (!block) return nullptr;
    *static_cast<Prefix*>(block) = {bytes, huge ? 1u : 0u};
    return static_cast<char*>(block) + sizeof(Prefix);
}

void decoderFree(void* data) {
    if (!data) return;
    Prefix* prefix = reinterpret_cast<Prefix*>(static_cast<char*>(data) - sizeof(Prefix));
    if (prefix->hugePages) candela::freeHugePages(prefix);
    else std::free(prefix);
}

void* decoderRealloc(void* data, size_t bytes) {
    if (!data) return decoderMalloc(bytes);
    Prefix* prefix = reinterpret_cast<Prefix*>(static_cast<char*>(data) - sizeof(Prefix));
    if (!prefix->hugePages && !(bytes >= kHugePage / 2)) {
        void* block = std::realloc(prefix, bytes + sizeof(Prefix));
        if (!block) return nullptr;
        static_cast<Prefix*>(block)->bytes = bytes;
        return static_cast<char*>(block) + sizeof(Prefix);
    }
    void* moved = decoderMalloc(bytes);
    if (!moved) return nullptr;
    std::memcpy(moved, data, std::min(bytes, prefix->bytes));
    decoderFree(data);
    return moved;
}

}  // namespace

#define STBI_MALLOC(bytes) decoderMalloc(bytes)
#define STBI_REALLOC(data, bytes) decoderRealloc(data, bytes)
#define STBI_FREE(data) decoderFree(data)
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
