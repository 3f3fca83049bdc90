#pragma once
// The little-endian fields of Candela's cache files (the IBL maps' `.cibl`, the levels of detail's
// `.clod`): written and read with a running wordHash64 (core/cache_files.h) of every byte, which
// those files end with as their checksum. Each file format keeps its own layout and checks; these are only the fields.

#include "core/cache_files.h"

#include <array>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <utility>

namespace candela {

// Writes little-endian fields to `sink`, a callable taking (const void* data, size_t size), hashing
// every byte written.
template <class Sink>
class CacheFieldWriter {
public:
    explicit CacheFieldWriter(Sink sink) : mSink(std::move(sink)) {}
    void bytes(const void* data, size_t size) {
        mSink(data, size);
        mHasher.update(data, size);
    }
    void u32(uint32_t v) {
        const std::array<uint8_t, 4> b = {uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)};
        bytes(b.data(), b.size());
    }
    void u64(uint64_t v) {
        u32(uint32_t(v));
        u32(uint32_t(v >> 32));
    }
    // wordHash64(0, every byte written so far).
    uint64_t hash() const { return mHasher.value(); }

private:
    Sink mSink;
    WordHasher mHasher;
};

// Reads little-endian fields from `source`, a callable bool(void* out, size_t size) that reads the
// next `size` bytes and says whether it could, of a file of `size` bytes; hashes every byte read.
// A read that would pass the end fails without calling the source, and a source that fails fails
// the read; either sets problem() ("truncated: the file ends (N bytes) inside WHAT", "read failed
// at byte N (WHAT): ..."), WHAT being the field's name as the caller gives it.
template <class Source>
class CacheFieldReader {
public:
    CacheFieldReader(uint64_t size, Source source) : mSource(std::move(source)), mSize(size) {}
    uint64_t offset() const { return mOffset; }
    uint64_t remaining() const { return mSize - mOffset; }
    // wordHash64(0, every byte read so far).
    uint64_t hash() const { return mHasher.value(); }
    const std::string& problem() const { return mProblem; }
    // Sets problem() to `problem` and returns false.
    bool fail(std::string problem) {
        mProblem = std::move(problem);
        return false;
    }
    bool bytes(void* out, uint64_t size, std::string_view what) {
        if (size > remaining())
            return fail("truncated: the file ends (" + std::to_string(mSize) + " bytes) inside " + std::string(what));
        if (size == 0) return true;
        if (!mSource(out, size_t(size)))
            return fail("read failed at byte " + std::to_string(mOffset) + " (" + std::string(what) + "): " + std::strerror(errno));
        mHasher.update(out, size_t(size));
        mOffset += size;
        return true;
    }
    bool u32(uint32_t& v, std::string_view what) {
        std::array<uint8_t, 4> b{};
        if (!bytes(b.data(), b.size(), what)) return false;
        v = uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
        return true;
    }
    bool u64(uint64_t& v, std::string_view what) {
        uint32_t lo = 0, hi = 0;
        if (!u32(lo, what) || !u32(hi, what)) return false;
        v = uint64_t(hi) << 32 | lo;
        return true;
    }

private:
    Source mSource;
    uint64_t mSize;
    uint64_t mOffset = 0;
    WordHasher mHasher;
    std::string mProblem;
};

// A source of CacheFieldReader over bytes in memory, read in order from the start.
struct CacheBytesSource {
    std::span<const std::byte> bytes;
    size_t at = 0;
    bool operator()(void* out, size_t size) {
        std::memcpy(out, bytes.data() + at, size);
        at += size;
        return true;
    }
};

}  // namespace candela
