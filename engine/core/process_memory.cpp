#include "core/process_memory.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <malloc.h>
#include <unistd.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace candela {

uint64_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    uint64_t sizePages = 0, residentPages = 0;
    if (!(statm >> sizePages >> residentPages)) return 0;
    return residentPages * static_cast<uint64_t>(sysconf(_SC_PAGESIZE));
}

uint64_t heapInUseBytes() {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    const struct mallinfo2 info = mallinfo2();
    return uint64_t(info.uordblks) + uint64_t(info.hblkhd);
#else
    return 0;
#endif
}

uint64_t heapMappedBytes() {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    return uint64_t(mallinfo2().hblkhd);
#else
    return 0;
#endif
}

void returnFreedHeapMemory() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

void adviseHugePages(void* data, size_t bytes) {
#if defined(__linux__)
    constexpr uintptr_t kHugePage = kHugePageBytes;
    const uintptr_t begin = (reinterpret_cast<uintptr_t>(data) + kHugePage - 1) & ~(kHugePage - 1);
    const uintptr_t end = (reinterpret_cast<uintptr_t>(data) + bytes) & ~(kHugePage - 1);
    if (data && end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // refused without THP: no matter
#else
    (void)data, (void)bytes;
#endif
}

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

#if defined(__linux__)
constexpr bool kMappedApart = !kAddressSanitizer;
#else
constexpr bool kMappedApart = false;
#endif

}  // namespace

bool hugePagesMappedApart() { return kMappedApart; }

void* allocateInHugePages(size_t bytes) {
    constexpr size_t kHugePage = kHugePageBytes, kPage = 4096;
    if (bytes > std::numeric_limits<size_t>::max() / 2) return nullptr;
    if (!kMappedApart) return std::malloc(std::max<size_t>(bytes, 1));
#if defined(__linux__)
    // A mapping with one 4 KiB page before the buffer, whose last word holds the buffer's size for
    // freeHugePages; the slack mapped to align the buffer is given back at once.
    const size_t rounded = (std::max<size_t>(bytes, 1) + kHugePage - 1) / kHugePage * kHugePage;
    const size_t reserved = kPage + rounded + kHugePage;
    void* mapped = mmap(nullptr, reserved, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) return nullptr;
    char* base = static_cast<char*>(mapped);
    char* data = reinterpret_cast<char*>((reinterpret_cast<uintptr_t>(base) + kPage + kHugePage - 1) & ~uintptr_t(kHugePage - 1));
    char* start = data - kPage;
    if (start > base) munmap(base, size_t(start - base));
    if (base + reserved > data + rounded) munmap(data + rounded, size_t(base + reserved - (data + rounded)));
    madvise(data, rounded, MADV_HUGEPAGE);  // refused without THP: no matter
    reinterpret_cast<size_t*>(data)[-1] = rounded;
    return data;
#else
    return nullptr;
#endif
}

void freeHugePages(void* data) {
    if (!data) return;
    if (!kMappedApart) {
        std::free(data);
        return;
    }
#if defined(__linux__)
    constexpr size_t kPage = 4096;
    munmap(static_cast<char*>(data) - kPage, kPage + static_cast<size_t*>(data)[-1]);
#endif
}

double processAgeMs() {
    std::ifstream in("/proc/self/stat");
    std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Field 22 (starttime) counts from the closing parenthesis of field 2 (the command may hold spaces).
    const size_t close = stat.rfind(')');
    if (close == std::string::npos) return -1.0;
    std::istringstream fields(stat.substr(close + 2));
    std::string field;
    for (int i = 3; i < 22 && fields >> field; ++i) {
    }
    unsigned long long startTicks = 0;
    if (!(fields >> startTicks)) return -1.0;
    const long ticksPerSecond = sysconf(_SC_CLK_TCK);
    timespec now{};
    if (ticksPerSecond <= 0 || clock_gettime(CLOCK_BOOTTIME, &now) != 0) return -1.0;
    const double nowMs = double(now.tv_sec) * 1000.0 + double(now.tv_nsec) * 1e-6;
    return nowMs - double(startTicks) * 1000.0 / double(ticksPerSecond);
}

}  // namespace candela
