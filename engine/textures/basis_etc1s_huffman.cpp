#include "textures/basis_etc1s_huffman.h"

#include <string>

namespace candela::textures::etc1s {
namespace {

constexpr uint32_t kMaxCodeLength = 16;

// Code-length code symbols (appendix "Compressed Huffman Tables"): 0..16 are lengths, then runs.
constexpr uint32_t kZeroRunShort = 17;   // 3 extra bits: 3..10 zero lengths
constexpr uint32_t kZeroRunLong = 18;    // 7 extra bits: 11..138 zero lengths
constexpr uint32_t kRepeatShort = 19;    // 2 extra bits: the previous length 3..6 times
constexpr uint32_t kCodeLengthCodes = 21;  // kRepeatLong = 20: 7 extra bits, the previous length 7..134 times

// The order in which the code-length codes' own 3-bit lengths are stored (codes_order).
constexpr std::array<uint8_t, kCodeLengthCodes> kCodeLengthOrder = {17, 18, 19, 20, 0, 8,  7, 9,  6, 10, 5,
                                                                    11, 4,  12, 3,  13, 2, 14, 1, 15, 16};

uint32_t reverseBits(uint32_t code, uint32_t length) {
    uint32_t reversed = 0;
    for (uint32_t i = 0; i < length; ++i) reversed = (reversed << 1) | ((code >> i) & 1);
    return reversed;
}

}  // namespace

HuffmanTable::HuffmanTable(std::span<const uint8_t> codeLengths) : mSymbolCount(uint32_t(codeLengths.size())) {
    for (const uint8_t length : codeLengths) {
        if (length > kMaxCodeLength) throw StreamError("Huffman code length " + std::to_string(length) + " above 16");
        if (length) ++mLengthCount[length];
    }
    for (uint32_t length = 1; length <= kMaxCodeLength; ++length) mUsedCount += mLengthCount[length];

    // Kraft sum: with two or more codes the lengths must fill the code space exactly (the canonical
    // codes are then a complete prefix code). One code may leave it partly empty (see the header).
    int64_t room = 1;
    for (uint32_t length = 1; length <= kMaxCodeLength; ++length) {
        room = room * 2 - mLengthCount[length];
        if (room < 0) throw StreamError("Huffman code lengths oversubscribe the code");
    }
    if (mUsedCount > 1 && room != 0) throw StreamError("Huffman code lengths leave the code incomplete");

    // Canonical codes (RFC 1951 section 3.2.2): by length, then by symbol; the first code of each
    // length follows the last code of the previous length, shifted left.
    std::array<uint32_t, kMaxCodeLength + 2> offset{};  // index in mSorted of each length's first symbol
    for (uint32_t length = 1; length <= kMaxCodeLength; ++length)
        offset[length + 1] = offset[length] + mLengthCount[length];
    mSorted.resize(mUsedCount);
    std::array<uint32_t, kMaxCodeLength + 1> nextCode{};  // mLengthCount[0] stays 0: unused symbols are not counted
    for (uint32_t length = 1, code = 0; length <= kMaxCodeLength; ++length) {
        code = (code + mLengthCount[length - 1]) << 1;
        nextCode[length] = code;
    }
    mFast.assign(size_t(1) << kFastBits, 0);
    for (uint32_t symbol = 0; symbol < mSymbolCount; ++symbol) {
        const uint32_t length = codeLengths[symbol];
        if (!length) continue;
        mSorted[offset[length]++] = uint16_t(symbol);
        const uint32_t code = nextCode[length]++;
        if (length > kFastBits) continue;
        // The stream sends a code's most significant bit first while the reader fills bit 0 first,
        // so the fast table is indexed by the reversed code, repeated for every value of the bits after it.
        for (uint32_t index = reverseBits(code, length); index < mFast.size(); index += 1u << length)
            mFast[index] = symbol << 5 | length;
    }
}

BitReader::BitReader(std::span<const uint8_t> bytes) : mNext(bytes.data()), mEnd(bytes.data() + bytes.size()) {}

void BitReader::refill() {
    while (mBuffered <= 56) {
        uint64_t byte = 0;
        if (mNext != mEnd)
            byte = *mNext++;
        else
            mPadding += 8;
        mBuffer |= byte << mBuffered;
        mBuffered += 8;
    }
}

void BitReader::consume(uint32_t count) {
    // The padding sits above the stream's own bits: reaching into it means reading past the end.
    if (mBuffered - count < mPadding) throw StreamError("the stream ends early");
    mBuffer >>= count;
    mBuffered -= count;
}

uint32_t BitReader::bits(uint32_t count) {
    if (count == 0) return 0;
    if (mBuffered < count) refill();
    const uint32_t value = uint32_t(mBuffer & ((uint64_t(1) << count) - 1));
    consume(count);
    return value;
}

uint32_t BitReader::huffman(const HuffmanTable& table) {
    if (table.mUsedCount == 0) throw StreamError("a symbol read from a Huffman table without codes");
    if (mBuffered < kMaxCodeLength) refill();
    const uint32_t fast = table.mFast[mBuffer & ((1u << HuffmanTable::kFastBits) - 1)];
    if (fast) {
        consume(fast & 31);
        return fast >> 5;
    }
    // Longer codes (and bits that are no code): walk the canonical code one bit at a time, as
    // RFC 1951's decoders do: `code` is the bits so far, `first` the first code of this length.
    uint32_t code = 0, first = 0, index = 0;
    for (uint32_t length = 1; length <= kMaxCodeLength; ++length) {
        code |= uint32_t(mBuffer >> (length - 1)) & 1;
        const uint32_t count = table.mLengthCount[length];
        if (code - first < count) {
            consume(length);
            return table.mSorted[index + code - first];
        }
        index += count;
        first = (first + count) << 1;
        code <<= 1;
    }
    throw StreamError("bits that are no code of their Huffman table");
}

uint32_t BitReader::vlc(uint32_t chunkBits) {
    uint32_t value = 0;
    for (uint32_t shift = 0;; shift += chunkBits) {
        if (shift >= 32) throw StreamError("a variable-length integer longer than 32 bits");
        const uint32_t chunk = bits(chunkBits + 1);
        value |= (chunk & ((1u << chunkBits) - 1)) << shift;
        if (!(chunk >> chunkBits)) return value;
    }
}

HuffmanTable BitReader::huffmanTable() {
    const uint32_t symbolCount = bits(14);
    if (symbolCount == 0) return {};
    const uint32_t storedLengths = bits(5);
    if (storedLengths < 1 || storedLengths > kCodeLengthCodes)
        throw StreamError("Huffman table with " + std::to_string(storedLengths) + " code-length codes (1..21)");
    std::array<uint8_t, kCodeLengthCodes> codeLengthLengths{};
    for (uint32_t i = 0; i < storedLengths; ++i) codeLengthLengths[kCodeLengthOrder[i]] = uint8_t(bits(3));
    const HuffmanTable codeLengthTable(codeLengthLengths);

    std::vector<uint8_t> lengths(symbolCount, 0);
    uint32_t next = 0;
    while (next < symbolCount) {
        const uint32_t symbol = huffman(codeLengthTable);
        if (symbol <= kMaxCodeLength) {
            lengths[next++] = uint8_t(symbol);
            continue;
        }
        uint32_t run = 0;
        uint8_t length = 0;
        if (symbol == kZeroRunShort) {
            run = bits(3) + 3;
        } else if (symbol == kZeroRunLong) {
            run = bits(7) + 11;
        } else {
            if (next == 0 || lengths[next - 1] == 0)
                throw StreamError("Huffman table repeats a code length where there is none to repeat");
            length = lengths[next - 1];
            run = symbol == kRepeatShort ? bits(2) + 3 : bits(7) + 7;
        }
        if (run > symbolCount - next) throw StreamError("Huffman table code lengths run past its symbol count");
        for (uint32_t end = next + run; next < end; ++next) lengths[next] = length;
    }
    return HuffmanTable(lengths);
}

}  // namespace candela::textures::etc1s
