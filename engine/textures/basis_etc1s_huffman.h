#pragma once
// The bit-level layer of BasisLZ (KTX 2.0 specification, appendix "BasisLZ/ETC1S Bitstream
// Specification"): an LSB-first bit reader, canonical Huffman tables as the appendix's "Compressed
// Huffman Tables" section stores them (RFC 1951 style code lengths, themselves Huffman and run-length
// coded), and the VLC integers of "ETC1S VLC Decoding Procedure". Private to basis_etc1s.cpp.
//
// Every read is checked: a stream that ends early, a malformed table or a bit pattern that is no
// code throws StreamError, which the public BasisLZ functions turn into a candela::UserError naming
// the section. Reading never touches a byte outside the span it was given.

#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace candela::textures::etc1s {

// A problem in a BasisLZ bit stream, without the context (which section or image) the caller adds.
class StreamError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A canonical Huffman code of up to 16383 symbols and 16-bit codes (appendix "Compressed Huffman
// Tables": compatible with RFC 1951 section 3.2.2). A table whose code lengths leave the code
// incomplete or oversubscribe it is refused when built, except for the two degenerate forms the
// Basis Universal tools write: a single used symbol (its code is all zeros; any other bits are no
// code) and a table whose symbols all have length 0 (stored for a stream that never uses it;
// decoding from it throws).
class HuffmanTable {
public:
    HuffmanTable() = default;

    // Builds the decoding tables from each symbol's code length (0 = unused, at most 16).
    // Throws StreamError when the lengths do not form a prefix code as described above.
    explicit HuffmanTable(std::span<const uint8_t> codeLengths);

    // The table's symbol count (the stored total_used_syms): 0 when the stream stores no table.
    uint32_t symbolCount() const { return mSymbolCount; }

private:
    friend class BitReader;
    static constexpr uint32_t kFastBits = 10;

    uint32_t mSymbolCount = 0;
    uint32_t mUsedCount = 0;              // symbols with a code
    std::vector<uint32_t> mFast;          // next kFastBits stream bits -> symbol << 5 | length; 0: longer code
    std::array<uint16_t, 17> mLengthCount{};  // codes of each length 1..16
    std::vector<uint16_t> mSorted;        // symbols with a code, in canonical order (length, then symbol)
};

// Reads bits least significant first from a byte span (the order of every BasisLZ stream).
class BitReader {
public:
    explicit BitReader(std::span<const uint8_t> bytes);

    // The next `count` bits (count <= 32) as an unsigned integer, first bit in the lowest place.
    uint32_t bits(uint32_t count);

    // The next symbol of `table`. Throws StreamError for a table without codes or bits that are no code.
    uint32_t huffman(const HuffmanTable& table);

    // decode_vlc4 (chunkBits 4) and decode_vlc7 (chunkBits 7): chunks of chunkBits value bits and a
    // continuation bit, least significant chunk first; at most 32 value bits.
    uint32_t vlc(uint32_t chunkBits);

    // read_huffman_table(): a table stored as the appendix's "Compressed Huffman Tables" describes.
    HuffmanTable huffmanTable();

private:
    void refill();
    void consume(uint32_t count);

    const uint8_t* mNext;
    const uint8_t* mEnd;
    uint64_t mBuffer = 0;     // unread bits, the next one in bit 0
    uint32_t mBuffered = 0;   // bits in mBuffer
    uint32_t mPadding = 0;    // of those, zero bits appended past the end of the span (the top ones)
};

}  // namespace candela::textures::etc1s
