#pragma once
// Rewrites KTX2 test files for the container tests: splits a file into its parts (header fields,
// DFD, key/value data, global data, levels) and writes it back with other parts — levels
// Zstandard-compressed, other key/value entries — laid out as the KTX 2.0 specification does
// (DFD and key/value data 4-byte aligned, global data 8-byte aligned, levels smallest first).

#include <zstd.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace candela::test {

struct Ktx2Parts {
    uint32_t fields[9] = {};  // vkFormat … supercompressionScheme, as in the header
    std::vector<uint8_t> dfd, kvd, sgd;
    std::vector<std::vector<uint8_t>> levels;  // level 0 first, as stored
    std::vector<uint64_t> uncompressed;        // per level: uncompressedByteLength
};

inline uint64_t ktx2Read(const std::vector<uint8_t>& b, size_t at, size_t bytes) {
    uint64_t v = 0;
    std::memcpy(&v, b.data() + at, bytes);
    return v;
}

inline Ktx2Parts splitKtx2(const std::vector<uint8_t>& file) {
    Ktx2Parts parts;
    for (int i = 0; i < 9; ++i) parts.fields[i] = uint32_t(ktx2Read(file, 12 + 4 * size_t(i), 4));
    const auto slice = [&](uint64_t offset, uint64_t length) {
        return std::vector<uint8_t>(file.begin() + ptrdiff_t(offset), file.begin() + ptrdiff_t(offset + length));
    };
    parts.dfd = slice(ktx2Read(file, 48, 4), ktx2Read(file, 52, 4));
    parts.kvd = slice(ktx2Read(file, 56, 4), ktx2Read(file, 60, 4));
    parts.sgd = slice(ktx2Read(file, 64, 8), ktx2Read(file, 72, 8));
    for (uint32_t level = 0; level < std::max(parts.fields[7], 1u); ++level) {
        const size_t at = 80 + 24 * size_t(level);
        parts.levels.push_back(slice(ktx2Read(file, at, 8), ktx2Read(file, at + 8, 8)));
        parts.uncompressed.push_back(ktx2Read(file, at + 16, 8));
    }
    return parts;
}

inline std::vector<uint8_t> joinKtx2(const Ktx2Parts& parts) {
    static const uint8_t kIdentifier[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
    std::vector<uint8_t> out(kIdentifier, kIdentifier + 12);
    const auto put = [&](uint64_t v, size_t bytes) {
        for (size_t i = 0; i < bytes; ++i) out.push_back(uint8_t(v >> (8 * i)));
    };
    const auto patch = [&](size_t at, uint64_t v, size_t bytes) {
        for (size_t i = 0; i < bytes; ++i) out[at + i] = uint8_t(v >> (8 * i));
    };
    const auto align = [&](size_t to) {
        while (out.size() % to) out.push_back(0);
    };
    for (uint32_t field : parts.fields) put(field, 4);
    out.resize(80 + 24 * parts.levels.size(), 0);  // section offsets and the level index, patched below
    align(4);
    patch(48, out.size(), 4);
    patch(52, parts.dfd.size(), 4);
    out.insert(out.end(), parts.dfd.begin(), parts.dfd.end());
    if (!parts.kvd.empty()) {
        align(4);
        patch(56, out.size(), 4);
        out.insert(out.end(), parts.kvd.begin(), parts.kvd.end());
    }
    patch(60, parts.kvd.size(), 4);
    if (!parts.sgd.empty()) {
        align(8);
        patch(64, out.size(), 8);
        out.insert(out.end(), parts.sgd.begin(), parts.sgd.end());
    }
    patch(72, parts.sgd.size(), 8);
    for (size_t level = parts.levels.size(); level-- > 0;) {  // smallest first
        align(parts.fields[8] == 0 ? 16 : 1);
        const size_t at = 80 + 24 * level;
        patch(at, out.size(), 8);
        patch(at + 8, parts.levels[level].size(), 8);
        patch(at + 16, parts.uncompressed[level], 8);
        out.insert(out.end(), parts.levels[level].begin(), parts.levels[level].end());
    }
    return out;
}

// The file with every level Zstandard-compressed (supercompressionScheme 2). Precondition: a
// UASTC file without supercompression.
inline std::vector<uint8_t> withZstandard(const std::vector<uint8_t>& file, int level = 6) {
    Ktx2Parts parts = splitKtx2(file);
    parts.fields[8] = 2;
    for (std::vector<uint8_t>& data : parts.levels) {
        std::vector<uint8_t> packed(ZSTD_compressBound(data.size()));
        const size_t size = ZSTD_compress(packed.data(), packed.size(), data.data(), data.size(), level);
        if (ZSTD_isError(size)) throw std::runtime_error(ZSTD_getErrorName(size));
        packed.resize(size);
        data = std::move(packed);
    }
    return joinKtx2(parts);
}

// Key/value data holding the given entries (key, value), each NUL-terminated and padded to 4 bytes.
inline std::vector<uint8_t> ktx2KeyValues(const std::vector<std::pair<std::string, std::string>>& entries) {
    std::vector<uint8_t> out;
    for (const auto& [key, value] : entries) {
        const uint32_t length = uint32_t(key.size() + 1 + value.size() + 1);
        for (int i = 0; i < 4; ++i) out.push_back(uint8_t(length >> (8 * i)));
        out.insert(out.end(), key.begin(), key.end());
        out.push_back(0);
        out.insert(out.end(), value.begin(), value.end());
        out.push_back(0);
        while (out.size() % 4) out.push_back(0);
    }
    return out;
}

}  // namespace candela::test
