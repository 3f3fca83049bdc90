#pragma once
// The process's resident set size (host memory actually in RAM), for the soak measurements, and
// its age (the time-to-image profile).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <new>

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
// A transparent huge page's size, and the buffer size from which whole huge pages pay (half of one:
// clearing a huge page costs a fraction of 512 faults of 4 KiB).
inline constexpr size_t kHugePageBytes = size_t(2) << 20;
inline constexpr size_t kHugePagesWorthBytes = kHugePageBytes / 2;
// Uninitialized memory for a large buffer its user fills, `bytes` of it usable. Where
// hugePagesMappedApart(): whole 2 MiB pages mapped on their own, aligned to 2 MiB and advised as
// above, so that all of it faults 2 MiB at a time and freeing it returns it to the system at once
// (the C heap would keep it, huge pages and all). Elsewhere a plain heap block. Null when the
// allocation fails or `bytes` is absurd.
void* allocateInHugePages(size_t bytes);
// Frees what allocateInHugePages returned; null: nothing.
void freeHugePages(void* data);
// Whether allocateInHugePages maps its buffers apart: on Linux, but not under AddressSanitizer,
// which checks every byte's use of heap blocks only.
bool hugePagesMappedApart();

// A buffer of `count` uninitialized T (trivially copyable) in huge pages when it is large enough
// for them to pay (kHugePagesWorthBytes), else from the C heap; owns its memory. Throws
// std::bad_alloc when the allocation fails.
template <typename T>
class ScratchBuffer {
public:
    explicit ScratchBuffer(size_t count) : mHuge(count * sizeof(T) >= kHugePagesWorthBytes) {
        void* data = mHuge ? allocateInHugePages(count * sizeof(T)) : ::operator new(std::max<size_t>(count, 1) * sizeof(T), std::nothrow);
        if (!data) throw std::bad_alloc();
        mData = static_cast<T*>(data);
    }
    ScratchBuffer(const ScratchBuffer&) = delete;
    ScratchBuffer& operator=(const ScratchBuffer&) = delete;
    ~ScratchBuffer() {
        if (mHuge) freeHugePages(mData);
        else ::operator delete(mData);
    }
    T* data() const { return mData; }

private:
    bool mHuge;
    T* mData = nullptr;
};
// Milliseconds since the process was created (Linux: /proc/self/stat's start time, in clock ticks
// of 10 ms, against CLOCK_BOOTTIME); negative where not available.
double processAgeMs();

}  // namespace candela
