// core/process_memory.h allocateInHugePages / freeHugePages: `bytes` usable (AddressSanitizer sees
// exactly those in the sanitized build); where the buffers are mapped apart, whole 2 MiB pages
// aligned to one and given back to the system when freed, not kept by the C heap; ScratchBuffer
// takes them only where they pay. The huge-page advice itself is best effort and not observable.
#include "core/process_memory.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

namespace candela {
namespace {

TEST(ProcessMemory, HugePageAllocationsHoldTheirBytesAlignedWhereMappedApart) {
    for (const size_t bytes : {size_t(1), size_t(1) << 20, kHugePageBytes, kHugePageBytes + 1, size_t(5) << 20}) {
        SCOPED_TRACE(bytes);
        void* data = allocateInHugePages(bytes);
        ASSERT_NE(data, nullptr);
        if (hugePagesMappedApart()) {
            EXPECT_EQ(reinterpret_cast<uintptr_t>(data) % kHugePageBytes, 0u);
        }
        std::memset(data, 0x5A, bytes);
        EXPECT_EQ(static_cast<const uint8_t*>(data)[bytes - 1], 0x5A);
        freeHugePages(data);
    }
    freeHugePages(nullptr);
    EXPECT_EQ(allocateInHugePages(~size_t(0) - 100), nullptr) << "an absurd size does not wrap around";
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

TEST(ProcessMemory, ScratchBuffersTakeHugePagesWhereTheyPay) {
    const ScratchBuffer<uint32_t> small(16), large(kHugePagesWorthBytes / sizeof(uint32_t));
    small.data()[15] = 7;
    large.data()[kHugePagesWorthBytes / sizeof(uint32_t) - 1] = 7;
    if (hugePagesMappedApart()) {
        EXPECT_EQ(reinterpret_cast<uintptr_t>(large.data()) % kHugePageBytes, 0u);
    }
    EXPECT_EQ(small.data()[15] + large.data()[kHugePagesWorthBytes / sizeof(uint32_t) - 1], 14u);
    const ScratchBuffer<uint32_t> empty(0);
    EXPECT_NE(empty.data(), nullptr);
}

}  // namespace
}  // namespace candela
