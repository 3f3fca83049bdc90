#include "assets/stb_image_decoder.h"

#include "core/process_memory.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <unordered_map>

namespace {

// stb_image's blocks of at least half a huge page (a 2048² JPEG's output, its 1 MiB chroma planes)
// come from allocateInHugePages (core/process_memory.h: whole huge pages, given back when freed),
// and are remembered here with their sizes; the rest from the C heap.
std::mutex gHugeBlocksMutex;
std::unordered_map<void*, size_t> gHugeBlocks;

// The caller's buffer for this thread's decode (loadRgba8Into): handed out once, to the first
// allocation of its size or one byte more (a JPEG's output asks for width × height × 4 + 1), and
// never freed or resized here (a block moved out of it is copied, the buffer left as it is).
struct Adopted {
    uint8_t* buffer = nullptr;
    size_t bytes = 0;  // the buffer holds bytes + 1
    bool handedOut = false;
};
thread_local Adopted tAdopted;

void* decoderMalloc(size_t bytes) {
    if (tAdopted.buffer && !tAdopted.handedOut && (bytes == tAdopted.bytes || bytes == tAdopted.bytes + 1)) {
        tAdopted.handedOut = true;
        return tAdopted.buffer;
    }
    if (bytes < candela::kHugePagesWorthBytes) return std::malloc(bytes);
    void* data = candela::allocateInHugePages(bytes);
    if (!data) return nullptr;
    try {
        const std::lock_guard lock(gHugeBlocksMutex);
        gHugeBlocks.emplace(data, bytes);
    } catch (...) {
        candela::freeHugePages(data);
        return nullptr;
    }
    return data;
}

// The size of `data` when it is a huge block (forgotten with `forget`), else 0.
size_t hugeBlockBytes(void* data, bool forget) {
    const std::lock_guard lock(gHugeBlocksMutex);
    const auto it = gHugeBlocks.find(data);
    if (it == gHugeBlocks.end()) return 0;
    const size_t bytes = it->second;
    if (forget) gHugeBlocks.erase(it);
    return bytes;
}

void decoderFree(void* data) {
    if (!data || data == tAdopted.buffer) return;
    if (hugeBlockBytes(data, true)) candela::freeHugePages(data);
    else std::free(data);
}

// A heap block stays in the heap (realloc); a huge block, or the caller's buffer, moves to a new
// block of `bytes` (decoderFree then gives back the huge block and leaves the buffer alone).
void* decoderRealloc(void* data, size_t bytes) {
    const size_t oldBytes = !data ? 0 : data == tAdopted.buffer ? tAdopted.bytes + 1 : hugeBlockBytes(data, false);
    if (oldBytes == 0) return std::realloc(data, bytes);
    void* moved = decoderMalloc(bytes);
    if (!moved) return nullptr;
    std::memcpy(moved, data, std::min(bytes, oldBytes));
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

bool loadRgba8Into(std::span<const uint8_t> bytes, int& width, int& height, std::vector<uint8_t>& out) {
    const size_t size = out.size();
    if (size == 0) return false;
    out.resize(size + 1);  // the byte a JPEG's output asks for beyond the pixels, inside out's size
    stbi_uc* pixels = nullptr;
    bool adopted = false;
    {
        struct Handed {  // this thread's record, cleared however the decode ends
            Handed(uint8_t* buffer, size_t bytes) { tAdopted = {buffer, bytes, false}; }
            ~Handed() { tAdopted = {}; }
        } handed(out.data(), size);
        int channels = 0;
        pixels = stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4);
        adopted = pixels && pixels == tAdopted.buffer;
    }
    out.resize(size);
    if (!pixels) return false;
    if (!adopted) {
        if (size_t(width) * size_t(height) * 4 == size) std::memcpy(out.data(), pixels, size);
        stbi_image_free(pixels);
    }
    return true;
}

Pixels<uint16_t> loadRgba16(std::span<const uint8_t> bytes, int& width, int& height) {
    int channels = 0;
    return Pixels<uint16_t>(stbi_load_16_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4));
}

const char* failureReason() { return stbi_failure_reason(); }

}  // namespace candela::assets::stb
