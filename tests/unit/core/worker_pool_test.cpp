// WorkerPool (core/worker_pool.h): each job runs once — on a worker, on the thread that needs it
// first, or never when cancelled — soon jobs go before background ones, and destruction drops
// what nobody started.
#include "core/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <thread>

namespace candela {
namespace {

using Priority = WorkerPool::Priority;

TEST(WorkerPool, EveryJobRunsExactlyOnce) {
    std::atomic<int> runs[64] = {};
    std::vector<WorkerPool::JobHandle> jobs;
    {
        WorkerPool pool(3);
        for (int i = 0; i < 64; ++i) jobs.push_back(pool.submit([&runs, i] { ++runs[i]; }, i % 2 ? Priority::Soon : Priority::Background));
        for (int i = 0; i < 64; i += 3) WorkerPool::runOrWait(jobs[size_t(i)]);  // races the workers for some
        for (const auto& job : jobs) WorkerPool::runOrWait(job);
    }
    for (int i = 0; i < 64; ++i) EXPECT_EQ(runs[i].load(), 1) << i;
    for (const auto& job : jobs) EXPECT_TRUE(WorkerPool::finished(job));
}

TEST(WorkerPool, WithoutWorkersTheWaiterRunsTheJob) {
    WorkerPool pool(0);
    std::thread::id ranOn;
    const auto job = pool.submit([&] { ranOn = std::this_thread::get_id(); }, Priority::Soon);
    EXPECT_FALSE(WorkerPool::finished(job));
    WorkerPool::runOrWait(job);
    EXPECT_EQ(ranOn, std::this_thread::get_id());
}

TEST(WorkerPool, SoonJobsGoBeforeBackgroundOnes) {
    WorkerPool pool(1);
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    std::vector<int> order;
    std::mutex orderMutex;
    const auto record = [&](int i) {
        std::lock_guard lock(orderMutex);
        order.push_back(i);
    };
    std::atomic<bool> started{false};
    const auto blocker = pool.submit([&started, released] {
        started = true;
        released.wait();
    }, Priority::Soon);
    // The worker holds the blocker: the rest queue behind it.
    while (!started) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::vector<WorkerPool::JobHandle> jobs = {pool.submit([&] { record(1); }, Priority::Background),
                                               pool.submit([&] { record(2); }, Priority::Background),
                                               pool.submit([&] { record(3); }, Priority::Soon),
                                               pool.submit([&] { record(4); }, Priority::Soon)};
    release.set_value();
    for (const auto& job : jobs) {
        while (!WorkerPool::finished(job)) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_EQ(order, (std::vector<int>{3, 4, 1, 2}));
}

TEST(WorkerPool, CancelledAndUnclaimedJobsNeverRunAndReleaseWhatTheyHold) {
    auto held = std::make_shared<int>(7);
    std::atomic<int> runs{0};
    WorkerPool::JobHandle cancelled, dropped;
    {
        WorkerPool pool(0);  // nothing runs unless asked
        cancelled = pool.submit([held, &runs] { ++runs; }, Priority::Soon);
        dropped = pool.submit([held, &runs] { ++runs; }, Priority::Background);
        EXPECT_EQ(held.use_count(), 3);
        EXPECT_FALSE(WorkerPool::cancel(cancelled));
        EXPECT_EQ(held.use_count(), 2);  // released by the cancel, on this thread
    }
    EXPECT_EQ(held.use_count(), 1);  // the pool's destruction dropped the other
    EXPECT_EQ(runs.load(), 0);
    EXPECT_FALSE(WorkerPool::finished(cancelled));
    EXPECT_FALSE(WorkerPool::finished(dropped));
    WorkerPool::runOrWait(dropped);  // a dropped job: returns at once, runs nothing
    EXPECT_EQ(runs.load(), 0);
}

TEST(WorkerPool, DefaultThreadsLeaveACoreAndStayFew) {
    const uint32_t n = WorkerPool::defaultThreads();
    EXPECT_GE(n, 1u);
    EXPECT_LE(n, 3u);
}

}  // namespace
}  // namespace candela
