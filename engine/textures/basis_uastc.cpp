// UASTC LDR 4×4 decoding, written from the UASTC chapter of the Khronos Data Format Specification
// ("Universal ASTC Compressed Texture Images", the KDFS edition of Basis Universal's "UASTC Texture
// Specification"; "UASTC spec" below) and its ASTC chapter ("ASTC spec": endpoint unquantization,
// weight unquantization, weight application, partition pattern generation).
//
// A block is 128 bits read from the least significant bit of byte 0 upwards: a prefix-coded mode
// index, transcoding hints (skipped: they only speed up transcoding to BC1/ETC), a partition pattern
// index or a colour component selector, the packed trits or quints of the endpoints, the endpoints'
// low bits, then 16 (or 32, dual plane) weights. Every mode's layout is fixed, so once the mode is
// known no field can lie past bit 128 (checked at compile time below) and no input can make the
// decoder read out of bounds; the only invalid blocks are the reserved mode 19 and pattern indices
// past their table.

#include "textures/basis_uastc.h"

#include "core/errors.h"

#include <array>
#include <cassert>
#include <cstring>
#include <string>

namespace candela::textures {
namespace {

constexpr uint32_t kModeCount = 19;       // modes 0..18; the prefix code's 19 is reserved
constexpr uint32_t kSolidColourMode = 8;  // UASTC spec "Solid color blocks"

// ---- Mode index (UASTC spec table "UASTC Mode Index encoding") ----------------------------------
// A prefix code of 2 to 7 bits at bit 0: `value` is the code's bits, `length` its length.
struct ModeCode {
    uint8_t value, length, mode;
};
constexpr ModeCode kModeCodeList[] = {
    {0x00, 2, 11}, {0x02, 3, 10}, {0x06, 3, 12}, {0x01, 4, 0},  {0x09, 4, 18}, {0x03, 5, 3},  {0x07, 5, 7},
    {0x0B, 5, 5},  {0x0D, 5, 14}, {0x0F, 5, 9},  {0x13, 5, 4},  {0x17, 5, 8},  {0x1B, 5, 6},  {0x1D, 5, 2},
    {0x1F, 5, 13}, {0x15, 6, 16}, {0x25, 6, 17}, {0x35, 6, 1},  {0x05, 7, 15}, {0x45, 7, 19},
};

struct ModeLookup {
    uint8_t mode = 0xFF;  // 0xFF: no code matches (cannot happen: the code is complete, checked below)
    uint8_t length = 0;
};

// The mode of every value of a block's low 7 bits.
constexpr std::array<ModeLookup, 128> makeModeLookup() {
    std::array<ModeLookup, 128> table{};
    for (uint32_t bits = 0; bits < 128; ++bits)
        for (const ModeCode& code : kModeCodeList)
            if ((bits & ((1u << code.length) - 1)) == code.value) table[bits] = {code.mode, code.length};
    return table;
}
constexpr std::array<ModeLookup, 128> kModeLookup = makeModeLookup();

constexpr bool everyModeBitPatternDecodes() {
    for (const ModeLookup& entry : kModeLookup)
        if (entry.mode == 0xFF) return false;
    return true;
}
static_assert(everyModeBitPatternDecodes(), "the UASTC mode code is a complete prefix code");

// ---- Mode layouts ---------------------------------------------------------------------------------
// UASTC spec tables "Block configuration bits" (hint bits: BC1H0/BC1H1, ETC1F, ETC1D, ETCI0/1, ETCBI,
// ETC2T/ETC2M; then PAT or CSEL), "Endpoint bits for each mode" (num_ebits), "Block endpoint
// description" (ET/EQ fields), "UASTC weight bits for each mode" (num_wbits), and "UASTC to ASTC
// configuration mapping" (subsets, dual plane, colour endpoint mode).
enum class Packing : uint8_t { Bits, Trits, Quints };
enum class Patterns : uint8_t { None, TwoSubset, TwoSubsetMode7, ThreeSubset };

struct ModeLayout {
    uint8_t hintBits;       // transcoding hints after the mode code
    Patterns patterns;      // which PAT table, if any (PAT is 5 bits for two subsets, 4 for three)
    uint8_t subsets;        // 1..3
    bool dualPlane;         // a second weight per texel for one channel
    bool csel;              // a 2-bit CSEL field picks that channel (else alpha: mode 17)
    uint8_t components;     // endpoint components: 2 (luminance, alpha), 3 (RGB), 4 (RGBA)
    Packing packing;        // trits or quints above the endpoint bits
    uint8_t endpointBits;   // num_ebits
    uint8_t weightBits;     // num_wbits
};

constexpr ModeLayout kModes[kModeCount] = {
    /* 0 */ {15, Patterns::None, 1, false, false, 3, Packing::Trits, 6, 4},
    /* 1 */ {15, Patterns::None, 1, false, false, 3, Packing::Bits, 8, 2},
    /* 2 */ {15, Patterns::TwoSubset, 2, false, false, 3, Packing::Bits, 4, 3},
    /* 3 */ {15, Patterns::ThreeSubset, 3, false, false, 3, Packing::Trits, 2, 2},
    /* 4 */ {15, Patterns::TwoSubset, 2, false, false, 3, Packing::Quints, 3, 2},
    /* 5 */ {15, Patterns::None, 1, false, false, 3, Packing::Bits, 8, 3},
    /* 6 */ {15, Patterns::None, 1, true, true, 3, Packing::Quints, 5, 2},
    /* 7 */ {15, Patterns::TwoSubsetMode7, 2, false, false, 3, Packing::Quints, 3, 2},
    /* 8 */ {0, Patterns::None, 0, false, false, 4, Packing::Bits, 8, 0},  // solid colour, decoded apart
    /* 9 */ {23, Patterns::TwoSubset, 2, false, false, 4, Packing::Bits, 4, 2},
    /* 10 */ {17, Patterns::None, 1, false, false, 4, Packing::Trits, 4, 4},
    /* 11 */ {17, Patterns::None, 1, true, true, 4, Packing::Trits, 4, 2},
    /* 12 */ {17, Patterns::None, 1, false, false, 4, Packing::Trits, 6, 3},
    /* 13 */ {23, Patterns::None, 1, true, true, 4, Packing::Bits, 8, 1},
    /* 14 */ {23, Patterns::None, 1, false, false, 4, Packing::Bits, 8, 2},
    /* 15 */ {23, Patterns::None, 1, false, false, 2, Packing::Bits, 8, 4},
    /* 16 */ {23, Patterns::TwoSubset, 2, false, false, 2, Packing::Bits, 8, 2},
    /* 17 */ {23, Patterns::None, 1, true, false, 2, Packing::Bits, 8, 2},
    /* 18 */ {15, Patterns::None, 1, false, false, 3, Packing::Bits, 5, 5},
};

constexpr uint32_t kMaxEndpointValues = 18;  // 3 subsets × RGB × 2 (mode 3)
constexpr uint32_t kTritsPerPack = 5;        // ET: 5 trits in 8 bits (3^5 = 243 ≤ 256)
constexpr uint32_t kQuintsPerPack = 3;       // EQ: 3 quints in 7 bits (5^3 = 125 ≤ 128)

constexpr uint32_t patternBits(Patterns patterns) {
    return patterns == Patterns::None ? 0 : patterns == Patterns::ThreeSubset ? 4 : 5;
}

// Bits of the ET/EQ field holding `count` trits or quints: 8 and 7 for full packs, and for the last,
// partial pack the fewest bits that hold its largest value (UASTC spec "Block endpoint description":
// ET[1] of mode 0 holds one trit in 2 bits, ET[1] of modes 10..12 three trits in 5 bits).
constexpr uint32_t packBits(Packing packing, uint32_t count) {
    if (packing == Packing::Trits) {
        constexpr uint8_t kBits[6] = {0, 2, 4, 5, 7, 8};  // ceil(log2(3^count))
        return kBits[count];
    }
    constexpr uint8_t kBits[4] = {0, 3, 5, 7};  // ceil(log2(5^count))
    return kBits[count];
}

constexpr uint32_t endpointValueCount(const ModeLayout& m) { return uint32_t(m.components) * 2 * m.subsets; }

constexpr uint32_t endpointPackBits(const ModeLayout& m) {
    if (m.packing == Packing::Bits) return 0;
    const uint32_t perPack = m.packing == Packing::Trits ? kTritsPerPack : kQuintsPerPack;
    const uint32_t values = endpointValueCount(m);
    return (values / perPack) * packBits(m.packing, perPack) + packBits(m.packing, values % perPack);
}

constexpr uint32_t modeCodeLength(uint32_t mode) {
    for (const ModeCode& code : kModeCodeList)
        if (code.mode == mode) return code.length;
    return 0;
}

// The bit where the weights start, and the bits the mode uses in all (mode 8: its colour).
constexpr uint32_t weightsStart(uint32_t mode) {
    const ModeLayout& m = kModes[mode];
    return modeCodeLength(mode) + m.hintBits + patternBits(m.patterns) + (m.csel ? 2 : 0) + endpointPackBits(m) +
           endpointValueCount(m) * m.endpointBits;
}
constexpr uint32_t modeBitCount(uint32_t mode) {
    const ModeLayout& m = kModes[mode];
    if (mode == kSolidColourMode) return modeCodeLength(mode) + 4 * 8;
    const uint32_t planes = m.dualPlane ? 2 : 1;
    return weightsStart(mode) + 16 * planes * m.weightBits - m.subsets * planes;  // anchors: one bit fewer
}

constexpr bool everyModeFitsTheBlock() {
    for (uint32_t mode = 0; mode < kModeCount; ++mode)
        if (modeBitCount(mode) > 128 || endpointValueCount(kModes[mode]) > kMaxEndpointValues) return false;
    return true;
}
static_assert(everyModeFitsTheBlock(), "a UASTC mode layout runs past the 128-bit block");
// Where the UASTC spec's "UASTC mode encoding summary" tables start the weights.
static_assert(weightsStart(1) == 69 && weightsStart(2) == 73 && weightsStart(4) == 89 && weightsStart(6) == 66 &&
                  weightsStart(13) == 94 && weightsStart(15) == 62 && weightsStart(16) == 98 && weightsStart(17) == 61,
              "mode layouts disagree with the UASTC spec's mode encoding summary");

// ---- Partition patterns ---------------------------------------------------------------------------
// Each PAT value names an ASTC partition pattern index (UASTC spec tables "ASTC Partition Index for
// UASTC PAT values"); the subset of each texel is ASTC's select_partition() for a small block (ASTC
// spec "Partition Pattern Generation"), which reproduces the UASTC spec's partition tables.
constexpr uint16_t kTwoSubsetSeeds[] = {28,  20,  16,  29,  91,  9,   107, 72,  149, 204, 50,  114, 496, 17,  78,
                                        39,  252, 828, 43,  156, 116, 210, 476, 273, 684, 359, 246, 195, 694, 524};
constexpr uint16_t kTwoSubsetMode7Seeds[] = {36,  48,  61,  137, 161, 183, 226, 281, 302, 307,
                                             479, 495, 593, 594, 605, 799, 812, 988, 993};
constexpr uint16_t kThreeSubsetSeeds[] = {260, 74, 32, 156, 183, 15, 745, 0, 335, 902, 254};

constexpr uint32_t astcHash52(uint32_t p) {
    p ^= p >> 15;
    p -= p << 17;
    p += p << 7;
    p += p << 4;
    p ^= p >> 5;
    p += p << 16;
    p ^= p >> 7;
    p ^= p >> 3;
    p ^= p << 6;
    p ^= p >> 17;
    return p;
}

// ASTC's select_partition() for a 2D block of fewer than 31 texels (so coordinates are doubled).
constexpr uint8_t astcPartition(uint32_t seed, uint32_t x, uint32_t y, uint32_t partitionCount) {
    x <<= 1;
    y <<= 1;
    seed += (partitionCount - 1) * 1024;
    const uint32_t rnum = astcHash52(seed);
    uint32_t s[8];
    for (uint32_t i = 0; i < 8; ++i) {
        const uint32_t nibble = (rnum >> (4 * i)) & 0xF;
        s[i] = (nibble * nibble) & 0xFF;  // the spec squares 8-bit values
    }
    const uint32_t shA = (seed & 2) ? 4 : 5;
    const uint32_t shB = partitionCount == 3 ? 6 : 5;
    const uint32_t sh1 = (seed & 1) ? shA : shB;
    const uint32_t sh2 = (seed & 1) ? shB : shA;
    // z is 0, so seeds 9..12 (the z factors) drop out.
    const uint32_t a = ((s[0] >> sh1) * x + (s[1] >> sh2) * y + (rnum >> 14)) & 0x3F;
    const uint32_t b = ((s[2] >> sh1) * x + (s[3] >> sh2) * y + (rnum >> 10)) & 0x3F;
    const uint32_t c = partitionCount >= 3 ? ((s[4] >> sh1) * x + (s[5] >> sh2) * y + (rnum >> 6)) & 0x3F : 0;
    if (a >= b && a >= c) return 0;
    if (b >= c) return 1;
    return 2;
}

using Pattern = std::array<uint8_t, 16>;  // subset of texel y * 4 + x

template <size_t N>
constexpr std::array<Pattern, N> makePatterns(const uint16_t (&seeds)[N], uint32_t subsets) {
    std::array<Pattern, N> patterns{};
    for (size_t p = 0; p < N; ++p)
        for (uint32_t i = 0; i < 16; ++i) patterns[p][i] = astcPartition(seeds[p], i & 3, i >> 2, subsets);
    return patterns;
}
constexpr auto kTwoSubsetPatterns = makePatterns(kTwoSubsetSeeds, 2);
constexpr auto kTwoSubsetMode7Patterns = makePatterns(kTwoSubsetMode7Seeds, 2);
constexpr auto kThreeSubsetPatterns = makePatterns(kThreeSubsetSeeds, 3);
constexpr Pattern kOneSubset{};

// Every pattern uses each of its subsets, so a block has one anchor weight per subset and the weight
// bit counts above hold.
template <size_t N>
constexpr bool everySubsetUsed(const std::array<Pattern, N>& patterns, uint32_t subsets) {
    for (const Pattern& pattern : patterns) {
        uint32_t used = 0;
        for (uint8_t subset : pattern) used |= 1u << subset;
        if (used != (1u << subsets) - 1) return false;
    }
    return true;
}
static_assert(everySubsetUsed(kTwoSubsetPatterns, 2) && everySubsetUsed(kTwoSubsetMode7Patterns, 2) &&
              everySubsetUsed(kThreeSubsetPatterns, 3));

// Spot checks against the UASTC spec's partition tables.
static_assert(kTwoSubsetPatterns[0] == Pattern{0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1});
static_assert(kTwoSubsetPatterns[29] == Pattern{1, 0, 0, 1, 0, 0, 1, 1, 0, 1, 1, 0, 1, 1, 0, 0});
static_assert(kTwoSubsetMode7Patterns[18] == Pattern{1, 1, 1, 1, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0});
static_assert(kThreeSubsetPatterns[0] == Pattern{0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 2, 2, 1, 1, 2, 2});
static_assert(kThreeSubsetPatterns[8] == Pattern{2, 0, 1, 2, 2, 0, 1, 2, 2, 0, 1, 2, 2, 0, 1, 2});

// ---- Unquantization ------------------------------------------------------------------------------
// An endpoint value is its trit or quint (if any) above its num_ebits low bits; it maps to 0..255 as
// ASTC spec "Endpoint Unquantization" says: bit replication for bits only, else
// T = D × C + B; T ^= A; T = (A & 0x80) | (T >> 2) with A the lowest bit replicated to 9 bits, B a
// per-range arrangement of the other bits ("Color unquantization parameters") and D the trit/quint.
constexpr uint8_t unquantizeEndpoint(Packing packing, uint32_t bitCount, uint32_t bits, uint32_t tq) {
    if (packing == Packing::Bits) {
        uint32_t value = bits << (8 - bitCount);  // replicate from the most significant bit down
        for (uint32_t filled = bitCount; filled < 8; filled += bitCount) value |= value >> bitCount;
        return uint8_t(value);
    }
    const uint32_t a = (bits & 1) ? 0x1FF : 0;
    const uint32_t high = bits >> 1;  // the bits above a: "b", "cb", "dcb", …
    uint32_t b = 0, c = 0;
    if (packing == Packing::Trits) {
        switch (bitCount) {  // ranges 0..11, 0..47, 0..191: the ones UASTC uses
            case 2: b = high * 0x116, c = 93; break;                 // b000b0bb0
            case 4: b = (high << 6) | high, c = 22; break;           // dcb000dcb
            case 6: b = (high << 4) | (high >> 4), c = 5; break;     // fedcb000f
            default: break;
        }
    } else {
        switch (bitCount) {  // ranges 0..39, 0..159
            case 3: b = (high << 7) | (high << 1) | (high >> 1), c = 26; break;  // cb0000cbc
            case 5: b = (high << 5) | (high >> 3), c = 6; break;                  // edcb0000e
            default: break;
        }
    }
    const uint32_t t = ((tq * c + b) ^ a) & 0x1FF;
    return uint8_t((a & 0x80) | (t >> 2));
}
// The UASTC spec's unquantization tables ("UASTC unquantization data for Mode Index 3", "... 4 and
// 7", "... 10 and 11", "... 6", "... 0 and 12"), indexed by (trit or quint << num_ebits) | bits.
static_assert(unquantizeEndpoint(Packing::Trits, 2, 2, 0) == 69 && unquantizeEndpoint(Packing::Trits, 2, 3, 2) == 139);
static_assert(unquantizeEndpoint(Packing::Quints, 3, 2, 4) == 58 &&
              unquantizeEndpoint(Packing::Quints, 3, 7, 4) == 132);
static_assert(unquantizeEndpoint(Packing::Trits, 4, 15, 2) == 131 && unquantizeEndpoint(Packing::Trits, 4, 8, 1) == 70);
static_assert(unquantizeEndpoint(Packing::Quints, 5, 31, 4) == 129 &&
              unquantizeEndpoint(Packing::Quints, 5, 8, 1) == 33);
static_assert(unquantizeEndpoint(Packing::Trits, 6, 63, 2) == 129 &&
              unquantizeEndpoint(Packing::Trits, 6, 17, 1) == 222 &&
              unquantizeEndpoint(Packing::Trits, 6, 1, 1) == 254);
static_assert(unquantizeEndpoint(Packing::Bits, 5, 0b10110, 0) == 0b10110101);

// Weights are bits only: replicated to 6 bits, then 33..63 become 34..64 (ASTC spec "Weight
// Unquantization"; the UASTC spec's "UASTC unquantization values for weight expansion").
constexpr std::array<std::array<uint8_t, 32>, 6> makeWeightTable() {
    std::array<std::array<uint8_t, 32>, 6> table{};
    for (uint32_t bitCount = 1; bitCount <= 5; ++bitCount)
        for (uint32_t w = 0; w < (1u << bitCount); ++w) {
            uint32_t value = w << (6 - bitCount);
            for (uint32_t filled = bitCount; filled < 6; filled += bitCount) value |= value >> bitCount;
            table[bitCount][w] = uint8_t(value > 32 ? value + 1 : value);
        }
    return table;
}
constexpr auto kWeights = makeWeightTable();
static_assert(kWeights[2][2] == 43 && kWeights[3][4] == 37 && kWeights[4][8] == 35 && kWeights[5][16] == 34 &&
              kWeights[5][31] == 64 && kWeights[1][1] == 64);

// ---- Bits -----------------------------------------------------------------------------------------
// Sequential reads from bit 0 (byte 0's least significant bit) up. Callers never read past bit 128:
// the mode layouts are checked above.
class BlockBitReader {
public:
    explicit BlockBitReader(const uint8_t* block) {
        for (int i = 7; i >= 0; --i) {
            mLow = (mLow << 8) | block[i];
            mHigh = (mHigh << 8) | block[8 + i];
        }
    }
    void skip(uint32_t count) { mPosition += count; }
    uint32_t read(uint32_t count) {  // count ≤ 8
        if (count == 0) return 0;
        assert(mPosition + count <= 128);
        uint64_t bits;
        if (mPosition >= 64)
            bits = mHigh >> (mPosition - 64);
        else if (mPosition + count <= 64)
            bits = mLow >> mPosition;
        else
            bits = (mLow >> mPosition) | (mHigh << (64 - mPosition));
        mPosition += count;
        return uint32_t(bits) & ((1u << count) - 1);
    }

private:
    uint64_t mLow = 0, mHigh = 0;
    uint32_t mPosition = 0;
};

}  // namespace

bool decodeUastcBlock(const uint8_t* block, bool srgb, uint8_t* texels) {
    const ModeLookup lookup = kModeLookup[block[0] & 0x7F];
    if (lookup.mode >= kModeCount) return false;  // mode 19: reserved
    BlockBitReader bits(block);
    bits.skip(lookup.length);

    if (lookup.mode == kSolidColourMode) {  // R, G, B, A, then ETC1 hints (ignored)
        uint8_t colour[4];
        for (uint8_t& c : colour) c = uint8_t(bits.read(8));
        for (uint32_t i = 0; i < 16; ++i) std::memcpy(texels + 4 * i, colour, 4);
        return true;
    }

    const ModeLayout& m = kModes[lookup.mode];
    bits.skip(m.hintBits);

    const Pattern* pattern = &kOneSubset;
    if (m.patterns != Patterns::None) {
        const uint32_t index = bits.read(patternBits(m.patterns));
        switch (m.patterns) {
            case Patterns::TwoSubset:
                if (index >= kTwoSubsetPatterns.size()) return false;
                pattern = &kTwoSubsetPatterns[index];
                break;
            case Patterns::TwoSubsetMode7:
                if (index >= kTwoSubsetMode7Patterns.size()) return false;
                pattern = &kTwoSubsetMode7Patterns[index];
                break;
            default:
                if (index >= kThreeSubsetPatterns.size()) return false;
                pattern = &kThreeSubsetPatterns[index];
                break;
        }
    }
    // Dual plane: the channel (0 R … 3 A) that takes the second plane's weights (CSEL, or alpha).
    const uint32_t ccs = m.csel ? bits.read(2) : 3;

    // Endpoints: the ET/EQ packs come first, then each value's low bits, in the order
    // RL0 RH0 GL0 GH0 BL0 BH0 [AL0 AH0] RL1 … (LL LH AL AH for luminance-alpha modes). Trit or quint
    // k of a pack is digit k of the pack in base 3 or 5; packs of 243..255 (trits) or 125..127
    // (quints) just yield those digits, as the UASTC spec asks ("resilient to ET bytes containing
    // 243..255").
    const uint32_t valueCount = endpointValueCount(m);
    uint32_t tq[kMaxEndpointValues] = {};
    if (m.packing != Packing::Bits) {
        const uint32_t perPack = m.packing == Packing::Trits ? kTritsPerPack : kQuintsPerPack;
        const uint32_t base = m.packing == Packing::Trits ? 3 : 5;
        for (uint32_t first = 0; first < valueCount; first += perPack) {
            const uint32_t count = valueCount - first < perPack ? valueCount - first : perPack;
            uint32_t pack = bits.read(packBits(m.packing, count));
            for (uint32_t k = 0; k < count; ++k, pack /= base) tq[first + k] = pack % base;
        }
    }
    uint8_t endpoints[kMaxEndpointValues];
    for (uint32_t i = 0; i < valueCount; ++i)
        endpoints[i] = unquantizeEndpoint(m.packing, m.endpointBits, bits.read(m.endpointBits), tq[i]);

    // Weight indices in raster order (both planes' weights of a texel together); the first texel of
    // each subset (its "anchor") stores one bit fewer, its top bit being 0.
    const uint32_t planes = m.dualPlane ? 2 : 1;
    uint8_t weights[2][16];
    uint32_t subsetsSeen = 0;
    for (uint32_t i = 0; i < 16; ++i) {
        const uint32_t subset = (*pattern)[i];
        const uint32_t anchor = (subsetsSeen >> subset) & 1 ? 0 : 1;
        subsetsSeen |= 1u << subset;
        for (uint32_t p = 0; p < planes; ++p) weights[p][i] = uint8_t(bits.read(m.weightBits - anchor));
    }

    // Endpoints expanded to 16 bits (UASTC spec "Decoding pixel values": (C << 8) | C, or (C << 8) |
    // 0x80 in sRGB mode, for alpha too), then C = ((CL × (64 − W) + CH × W + 32) >> 6) >> 8: the top
    // byte of ASTC's UNORM16 interpolation result, as its decode_unorm8 mode gives it. Computed once
    // per subset and weight index (a palette of 2 to 32 colours), then looked up per texel.
    const uint32_t levels = 1u << m.weightBits;
    const uint8_t* unquantized = kWeights[m.weightBits].data();
    uint8_t palette[3][32][4];
    for (uint32_t s = 0; s < m.subsets; ++s) {
        const uint8_t* e = endpoints + s * m.components * 2;
        for (uint32_t c = 0; c < 4; ++c) {
            // Luminance-alpha modes give R, G and B the luminance; RGB modes have opaque alpha.
            const uint32_t source = m.components == 2 ? (c == 3 ? 1 : 0) : c;
            const bool opaque = m.components == 3 && c == 3;
            const uint32_t lo = opaque ? 255 : e[2 * source], hi = opaque ? 255 : e[2 * source + 1];
            const uint32_t low = (lo << 8) | (srgb ? 0x80 : lo), high = (hi << 8) | (srgb ? 0x80 : hi);
            for (uint32_t level = 0; level < levels; ++level) {
                const uint32_t w = unquantized[level];
                palette[s][level][c] = uint8_t(((low * (64 - w) + high * w + 32) >> 6) >> 8);
            }
        }
    }
    for (uint32_t i = 0; i < 16; ++i) std::memcpy(texels + 4 * i, palette[(*pattern)[i]][weights[0][i]], 4);
    if (planes == 2)  // dual-plane modes have one subset
        for (uint32_t i = 0; i < 16; ++i) texels[4 * i + ccs] = palette[0][weights[1][i]][ccs];
    return true;
}

void decodeUastcImage(std::span<const uint8_t> blocks, uint32_t width, uint32_t height, bool srgb,
                      std::span<uint8_t> rgba) {
    const uint32_t blocksX = (width + 3) / 4, blocksY = (height + 3) / 4;
    assert(width >= 1 && height >= 1);
    assert(blocks.size() == size_t(blocksX) * blocksY * 16);
    assert(rgba.size() == size_t(width) * height * 4);
    uint8_t texels[64];
    for (uint32_t by = 0; by < blocksY; ++by) {
        for (uint32_t bx = 0; bx < blocksX; ++bx) {
            const size_t index = size_t(by) * blocksX + bx;
            if (!decodeUastcBlock(blocks.data() + index * 16, srgb, texels))
                throw UserError("UASTC block " + std::to_string(index) + " at (" + std::to_string(bx) + ", " +
                                std::to_string(by) + "): invalid block");
            const uint32_t columns = width - bx * 4 < 4 ? width - bx * 4 : 4;
            const uint32_t rows = height - by * 4 < 4 ? height - by * 4 : 4;
            for (uint32_t y = 0; y < rows; ++y)
                std::memcpy(rgba.data() + (size_t(by * 4 + y) * width + bx * 4) * 4, texels + y * 16, columns * 4);
        }
    }
}

}  // namespace candela::textures
