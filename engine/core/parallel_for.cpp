#include "core/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace candela {

uint32_t hardwareThreads() { return std::max(1u, std::thread::hardware_concurrency()); }

void parallelFor(size_t count, const std::function<void(size_t)>& fn, uint32_t threads) {
    if (count == 0) return;
    const size_t used = std::min<size_t>(threads == 0 ? hardwareThreads() : threads, count);
    std::vector<std::exception_ptr> errors(count);
    std::atomic<size_t> next{0};
    const auto work = [&] {
        for (size_t i; (i = next.fetch_add(1)) < count;) {
            try {
                fn(i);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        }
    };
    std::vector<std::thread> helpers;
    helpers.reserve(used - 1);
    for (size_t t = 1; t < used; ++t) helpers.emplace_back(work);
    work();
    for (std::thread& helper : helpers) helper.join();
    for (const std::exception_ptr& error : errors)
        if (error) std::rethrow_exception(error);
}

void parallelForRows(uint32_t width, uint32_t rows, const std::function<void(uint32_t)>& fn) {
    constexpr uint32_t kBand = 16;
    if (uint64_t(width) * rows < 65536) {
        for (uint32_t y = 0; y < rows; ++y) fn(y);
        return;
    }
    parallelFor((rows + kBand - 1) / kBand, [&](size_t band) {
        for (uint32_t y = uint32_t(band) * kBand; y < std::min(rows, uint32_t(band + 1) * kBand); ++y) fn(y);
    });
}

}  // namespace candela
