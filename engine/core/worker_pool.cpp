#include "core/worker_pool.h"

#include <algorithm>
#include <atomic>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace candela {

class WorkerPool::Job {
public:
    explicit Job(std::function<void()> fn) : mFn(std::move(fn)) {}

    // Takes the job for this thread; false if someone else has (or it was cancelled).
    bool claim() { return !mClaimed.exchange(true); }
    // Precondition: claim() returned true on this thread.
    void run(bool execute) {
        if (execute) mFn();
        mFn = nullptr;  // what it captured goes here, before anyone learns the job is over
        {
            std::lock_guard lock(mMutex);
            mDone = true;
            mRan = execute;
        }
        mDoneChanged.notify_all();
    }
    void wait() {
        std::unique_lock lock(mMutex);
        mDoneChanged.wait(lock, [&] { return mDone; });
    }
    bool ran() {
        std::lock_guard lock(mMutex);
        return mDone && mRan;
    }

private:
    std::function<void()> mFn;
    std::atomic<bool> mClaimed{false};
    std::mutex mMutex;
    std::condition_variable mDoneChanged;
    bool mDone = false, mRan = false;
};

WorkerPool::WorkerPool(uint32_t threads) {
    for (uint32_t i = 0; i < threads; ++i) mThreads.emplace_back([this] { work(); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard lock(mMutex);
        mStop = true;
    }
    mWake.notify_all();
    for (std::thread& t : mThreads) t.join();
    // Jobs never claimed are dropped: their functions (and what they captured) go with the queue.
    for (const std::deque<JobHandle>* queue : {&mSoon, &mBackground})
        for (const JobHandle& job : *queue) cancel(job);
}

uint32_t WorkerPool::defaultThreads() {
    const uint32_t hardware = std::thread::hardware_concurrency();
    return std::clamp(hardware > 1 ? hardware - 1 : 1u, 1u, 3u);
}

WorkerPool::JobHandle WorkerPool::submit(std::function<void()> fn, Priority priority) {
    auto job = std::make_shared<Job>(std::move(fn));
    {
        std::lock_guard lock(mMutex);
        (priority == Priority::Soon ? mSoon : mBackground).push_back(job);
    }
    mWake.notify_one();
    return job;
}

void WorkerPool::runOrWait(const JobHandle& job) {
    if (job->claim()) job->run(true);
    else job->wait();
}

bool WorkerPool::cancel(const JobHandle& job) {
    if (job->claim()) {
        job->run(false);
        return false;
    }
    job->wait();
    return job->ran();
}

bool WorkerPool::finished(const JobHandle& job) { return job->ran(); }

void WorkerPool::work() {
#if defined(__linux__)
    // Background work yields to the thread drawing frames (per thread on Linux).
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
#endif
    for (;;) {
        JobHandle job;
        {
            std::unique_lock lock(mMutex);
            mWake.wait(lock, [&] { return mStop || !mSoon.empty() || !mBackground.empty(); });
            if (mStop) return;
            std::deque<JobHandle>& queue = mSoon.empty() ? mBackground : mSoon;
            job = std::move(queue.front());
            queue.pop_front();
        }
        if (job->claim()) job->run(true);
    }
}

}  // namespace candela
