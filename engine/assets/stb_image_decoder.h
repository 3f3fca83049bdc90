#pragma once
// Internal to the glTF loader: stb_image (Debian's header, the same version as its libstb) compiled
// into this library with its own allocator, so that the large buffers it decodes into (a 2048²
// JPEG's output and component planes: some 22 MiB) are whole transparent huge pages, mapped for
// them and given back when freed (core/process_memory.h allocateInHugePages): 4 KiB page faults
// otherwise cost a CPU device's single render more than the copies themselves. The functions are
// stb_image's, renamed; its implementation is private to stb_image_decoder.cpp.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace candela::assets::stb {

// Frees what loadRgba16 returns.
struct PixelsFree {
    void operator()(void* pixels) const;
};
template <typename T>
using Pixels = std::unique_ptr<T, PixelsFree>;

// stbi_info_from_memory: the declared size and channel count, without decoding. Precondition:
// bytes.size() fits in an int. False for data stb_image cannot read (failureReason() says why).
bool info(std::span<const uint8_t> bytes, int& width, int& height, int& channels);
// stbi_is_16_bit_from_memory: whether the image holds 16 bits per channel (PNG).
bool is16Bit(std::span<const uint8_t> bytes);
// stbi_load_from_memory with 4 channels (RGBA, top row first) into `out`, which the caller sized
// to the declared width × height × 4 (with a byte of spare capacity, or it is reallocated once):
// stb_image decodes into out's own storage (its first allocation of that size, or a byte more, is
// given out's), so the pixels are not copied; where it decodes elsewhere they are copied in.
// False where decoding fails (failureReason() says why) or out is empty; width and height are the
// decoded size, and out holds the pixels only where that is the declared one (the caller checks).
// Safe on several threads at once: the storage handed to stb_image is the calling thread's.
bool loadRgba8Into(std::span<const uint8_t> bytes, int& width, int& height, std::vector<uint8_t>& out);
// stbi_load_16_from_memory with 4 channels: null where decoding fails (failureReason() says why);
// width and height are the decoded size.
Pixels<uint16_t> loadRgba16(std::span<const uint8_t> bytes, int& width, int& height);
// stbi_failure_reason of the calling thread's last call above; null where there is none.
const char* failureReason();

}  // namespace candela::assets::stb
