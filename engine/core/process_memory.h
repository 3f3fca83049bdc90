#pragma once
// The process's resident set size (host memory actually in RAM), for the soak measurements.

#include <cstdint>

namespace candela {

// Bytes resident now (Linux: /proc/self/statm); 0 where that is not available.
uint64_t residentBytes();
// Bytes of the C heap in use by live allocations (glibc mallinfo2: small blocks + mmapped ones);
// unlike the RSS, not inflated by memory the allocator keeps cached. 0 where not available.
uint64_t heapInUseBytes();

}  // namespace candela
