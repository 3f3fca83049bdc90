#pragma once
// parallelFor: one loop's iterations spread over a few threads, the calling thread among them, for
// CPU work that is needed now (levels of detail, texture decoding) rather than ahead of its use
// (that is WorkerPool's). Iterations are handed out one at a time in order, so put the largest
// first when their costs differ.

#include <cstddef>
#include <cstdint>
#include <functional>

namespace candela {

// The threads parallelFor uses unless told: the hardware threads, at least 1.
uint32_t hardwareThreads();

// Calls fn(i) for every i in [0, count), on `threads` threads at most (the caller's included; 0:
// hardwareThreads()), and returns when every call has returned. When calls throw, the other
// iterations still run and the first exception (in iteration order) is rethrown here.
// Precondition: fn may be called concurrently for different i.
void parallelFor(size_t count, const std::function<void(size_t)>& fn, uint32_t threads = 0);

// Calls fn(y) for every row y in [0, rows) of an image `width` items wide: bands of 16 rows handed
// out by parallelFor, or all on the calling thread when the image holds fewer than 65,536 items
// (starting threads would cost more). Precondition: fn may be called concurrently for different rows.
void parallelForRows(uint32_t width, uint32_t rows, const std::function<void(uint32_t)>& fn);

}  // namespace candela
