#include "core/process_memory.h"

#include <fstream>
#include <malloc.h>
#include <unistd.h>

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

}  // namespace candela
