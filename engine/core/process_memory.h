#pragma once
// The process's resident set size (host memory actually in RAM), for the soak measurements.

#include <cstdint>

namespace candela {

// Bytes resident now (Linux: /proc/self/statm); 0 where that is not available.
uint64_t residentBytes();

}  // namespace candela
