// parallelFor (core/parallel_for.h): every iteration once, on more than one thread when asked, and
// the first exception in iteration order rethrown after the others ran; parallelForRows: every
// row once, a small image's on the calling thread alone.
#include "core/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace candela {
namespace {

TEST(ParallelFor, RunsEveryIterationOnceOnTheThreadsAsked) {
    std::vector<std::atomic<int>> calls(1000);
    std::mutex mutex;
    std::set<std::thread::id> threads;
    parallelFor(calls.size(), [&](size_t i) {
        ++calls[i];
        std::this_thread::yield();
        const std::lock_guard lock(mutex);
        threads.insert(std::this_thread::get_id());
    }, 3);
    for (const std::atomic<int>& c : calls) EXPECT_EQ(c.load(), 1);
    EXPECT_LE(threads.size(), 3u);
    EXPECT_TRUE(threads.count(std::this_thread::get_id())) << "the caller works too";
    parallelFor(0, [](size_t) { FAIL() << "no iteration"; });
}

TEST(ParallelFor, RethrowsTheFirstFailureAfterTheRestRan) {
    std::atomic<int> ran{0};
    try {
        parallelFor(50, [&](size_t i) {
            ++ran;
            if (i == 7 || i == 31) throw std::runtime_error("iteration " + std::to_string(i));
        }, 2);
        FAIL() << "nothing thrown";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "iteration 7");
    }
    EXPECT_EQ(ran.load(), 50);
}

TEST(ParallelForRows, RunsEveryRowOnceAndASmallImagesOnTheCaller) {
    for (const auto& [width, rows] : {std::pair{4096u, 37u}, std::pair{100u, 20u}, std::pair{1u, 0u}}) {
        std::vector<std::atomic<int>> calls(rows);
        std::mutex mutex;
        std::set<std::thread::id> threads;
        parallelForRows(width, rows, [&](uint32_t y) {
            ++calls[y];
            const std::lock_guard lock(mutex);
            threads.insert(std::this_thread::get_id());
        });
        for (const std::atomic<int>& c : calls) EXPECT_EQ(c.load(), 1) << width << " x " << rows;
        if (uint64_t(width) * rows < 65536) {
            EXPECT_TRUE(threads.empty() || threads == std::set{std::this_thread::get_id()}) << width << " x " << rows;
        }
    }
}

}  // namespace
}  // namespace candela
