#pragma once
// The process's resident set size (host memory actually in RAM), for the soak measurements, and
// its age (the time-to-image profile).

#include <cstddef>
#include <cstdint>

namespace candela {

// Bytes resident now (Linux: /proc/self/statm); 0 where that is not available.
uint64_t residentBytes();
// Bytes of the C heap in use by live allocations (glibc mallinfo2: small blocks + mmapped ones);
// unlike the RSS, not inflated by memory the allocator keeps cached. 0 where not available.
uint64_t heapInUseBytes();
// The part of heapInUseBytes() in blocks the allocator mapped on their own (glibc: allocations
// above its mmap threshold, 128 KiB growing to 32 MiB): a single large allocation alive when the
// sample is taken shows here whole. 0 where not available.
uint64_t heapMappedBytes();
// Gives the memory the C heap holds free back to the system (glibc: malloc_trim), so that the
// resident size shows what is in use (a run over many scenes, between scenes). No-op elsewhere.
void returnFreedHeapMemory();
// Advises the kernel that the 2 MiB-aligned interior of [data, data + bytes) is best backed by
// transparent huge pages (Linux madvise MADV_HUGEPAGE, where the system's THP mode allows it): the
// range's first touches then fault 2 MiB at a time instead of 4 KiB (large decoded images, a CPU
// device's memory). Best effort: pages already touched stay as they are, the advice outlives the
// caller's use of heap memory (a later allocation there may get huge pages too), and it is a no-op
// elsewhere, for ranges under 2 MiB, or where THP is off.
void adviseHugePages(void* data, size_t bytes);
// Uninitialized memory for a large buffer its user fills: `bytes` rounded up to whole 2 MiB pages,
// aligned to 2 MiB and advised as above, so that all of it faults 2 MiB at a time (a huge page is
// cleared for a fraction of the cost of 512 faults of 4 KiB). Where hugePagesMappedApart(), mapped
// on its own, so that freeing it returns it to the system at once (the C heap would keep it, huge
// pages and all); elsewhere from the C heap. Null when the allocation fails. Worth it from about
// 1 MiB (half a huge page) up.
void* allocateInHugePages(size_t bytes);
// Frees what allocateInHugePages returned; null: nothing.
void freeHugePages(void* data);
// Whether allocateInHugePages maps its buffers apart: on Linux, but not under AddressSanitizer,
// which checks every byte's use of heap blocks only.
bool hugePagesMappedApart();
// Milliseconds since the process was created (Linux: /proc/self/stat's start time, in clock ticks
// of 10 ms, against CLOCK_BOOTTIME); negative where not available.
double processAgeMs();

}  // namespace candela
