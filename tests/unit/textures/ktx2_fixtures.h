#pragma once
// The KTX2 fixtures of tests/data/ktx2 (made by tools/ktx2-test-data) as bytes, and what the
// BasisLZ and UASTC decoder tests read from them by hand, independently of the KTX2 loader: the
// little-endian header and level-index fields, and the size of a mip level.

#include "test_paths.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace candela::test {

inline std::filesystem::path ktx2FixtureDir() { return testData() / "ktx2"; }

// The bytes of fixture `name` ("uastc_mips.ktx2", "uastc_mips_l0.png"); throws when it is missing.
inline std::vector<uint8_t> readKtx2Fixture(const std::string& name) {
    const std::filesystem::path path = ktx2FixtureDir() / name;
    std::ifstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("cannot open " + path.string());
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// The little-endian field at byte `at` (KTX2 fields are little-endian, as is every test host).
inline uint32_t u32(const std::vector<uint8_t>& bytes, size_t at) {
    uint32_t value = 0;
    std::memcpy(&value, bytes.data() + at, 4);
    return value;
}
inline uint64_t u64(const std::vector<uint8_t>& bytes, size_t at) {
    uint64_t value = 0;
    std::memcpy(&value, bytes.data() + at, 8);
    return value;
}

// The width or height of mip `level` of an image `size` texels across.
inline uint32_t levelSize(uint32_t size, uint32_t level) { return std::max(1u, size >> level); }

}  // namespace candela::test
