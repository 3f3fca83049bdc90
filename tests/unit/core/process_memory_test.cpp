// core/process_memory.h allocateInHugePages / freeHugePages: whole 2 MiB pages, aligned to one,
// writable to the last byte of the rounded size, and (Linux) given back to the system when freed,
// not kept by the C heap. The huge-page advice itself is best effort and not observable here.
#include "core/process_memory.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

namespace candela {
namespace {

constexpr size_t kHugePage = size_t(2) << 20;

TEST(ProcessMemory, HugePageAllocationsAreAlignedWholePages) {
    for (const size_t bytes : {size_t(1), size_t(1) << 20, kHugePage, kHugePage + 1, size_t(5) << 20}) {
        SCOPED_TRACE(bytes);
        void* data = allocateInHugePages(bytes);
        ASSERT_NE(data, nullptr);
        EXPECT_EQ(reinterpret_cast<uintptr_t>(data) % kHugePage, 0u);
        // Every byte up to the rounded size is the caller's (AddressSanitizer reports a byte past it).
        const size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        std::memset(data, 0x5A, rounded);
        EXPECT_EQ(static_cast<const uint8_t*>(data)[rounded - 1], 0x5A);
        freeHugePages(data);
    }
    freeHugePages(nullptr);
}

TEST(ProcessMemory, FreedHugePagesLeaveTheResidentSet) {
    if (!hugePagesMappedApart()) GTEST_SKIP() << "from the C heap here (AddressSanitizer, or not Linux), which may keep them";
    constexpr size_t kBytes = size_t(64) << 20;
    const uint64_t before = residentBytes();
    ASSERT_GT(before, 0u);
    void* data = allocateInHugePages(kBytes);
    ASSERT_NE(data, nullptr);
    std::memset(data, 1, kBytes);
    EXPECT_GE(residentBytes(), before + kBytes * 9 / 10) << "touched, the buffer is resident";
    freeHugePages(data);
    EXPECT_LT(residentBytes(), before + kBytes / 10) << "freed, it is the system's again";
}

}  // namespace
}  // namespace candela
