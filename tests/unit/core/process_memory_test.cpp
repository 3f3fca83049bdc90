// core/process_memory.h allocateInHugePages: whole 2 MiB pages, aligned to one, writable to the last
// byte asked for and freed with std::free; the advice itself is best effort and not observable here.
#include "core/process_memory.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace candela {
namespace {

TEST(ProcessMemory, HugePageAllocationsAreAlignedWholePagesFreedWithFree) {
    constexpr size_t kHugePage = size_t(2) << 20;
    for (const size_t bytes : {size_t(1), size_t(1) << 20, kHugePage, kHugePage + 1, size_t(5) << 20}) {
        SCOPED_TRACE(bytes);
        void* data = allocateInHugePages(bytes);
        ASSERT_NE(data, nullptr);
        EXPECT_EQ(reinterpret_cast<uintptr_t>(data) % kHugePage, 0u);
        // Every byte up to the rounded size is the caller's (AddressSanitizer reports a byte past it).
        const size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        std::memset(data, 0x5A, rounded);
        EXPECT_EQ(static_cast<const uint8_t*>(data)[rounded - 1], 0x5A);
        std::free(data);
    }
}

}  // namespace
}  // namespace candela
