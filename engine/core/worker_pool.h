#pragma once
// WorkerPool: a few threads that run queued jobs, for work that may run ahead of its first use
// (pipelines compiled before they are drawn: vk/pipeline_cache.h). A job runs at most once — on a
// worker, or on the thread that needs it first (runOrWait), or never (cancel) — so whoever
// needs a result never waits behind a queue of work it does not need.
//
//     WorkerPool pool(WorkerPool::defaultThreads());
//     auto job = pool.submit([&] { result = build(); }, WorkerPool::Priority::Background);
//     ...
//     WorkerPool::runOrWait(job);  // result is set (or the job threw: see submit)
//
// The workers run at a lower scheduling priority (Linux nice +10) so that background work yields
// to the thread drawing frames. Destruction joins the workers after the job each is running;
// queued jobs nobody claimed are dropped without running.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace candela {

class WorkerPool {
public:
    // A queued job. Opaque; shared by the queue and the submitter.
    class Job;
    using JobHandle = std::shared_ptr<Job>;
    enum class Priority {
        Soon,        // before every Background job (needed by the frame being built)
        Background,  // after everything queued
    };

    // Starts `threads` workers (0: none; jobs then run only through runOrWait).
    explicit WorkerPool(uint32_t threads);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    // One less than the hardware threads, at least 1 and at most 3: with the thread that waits for
    // a result running jobs too, every core is used while a frame waits for its pipelines.
    static uint32_t defaultThreads();

    // Queues `fn`. Precondition: `fn` does not throw (catch inside and keep the error for whoever
    // needs the result). What `fn` captures is destroyed on the thread that ran it, before the job
    // counts as finished; a cancelled job's on the cancelling thread.
    JobHandle submit(std::function<void()> fn, Priority priority);
    // Runs `job` on this thread if nobody has started it; otherwise waits until it finished.
    static void runOrWait(const JobHandle& job);
    // Drops `job` if nobody has started it; otherwise waits until it finished. Returns whether it ran.
    static bool cancel(const JobHandle& job);
    // Whether `job` has finished running (false for a job cancelled before it started).
    static bool finished(const JobHandle& job);

    uint32_t threads() const { return static_cast<uint32_t>(mThreads.size()); }

private:
    void work();

    std::mutex mMutex;
    std::condition_variable mWake;
    std::deque<JobHandle> mSoon, mBackground;  // each in submission order
    bool mStop = false;
    std::vector<std::thread> mThreads;
};

}  // namespace candela
