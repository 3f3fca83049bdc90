#pragma once
// PipelineCache<Key>: the pipeline variants of one pass (specialization constants, target formats),
// each built once and kept — at its first use, or ahead of it on a worker thread (prepare). A
// later use of a variant refreshes it, so a shader replaced at run time (hot reload) rebuilds
// every variant of it at that variant's next use, while frames in flight keep the old pipeline
// (deferred deletion). Every pass with variants keeps one:
//
//   vk::PipelineCache<Variant> mPipelines;  // Variant: any copyable type with operator<
//   const vk::Pipeline& p = mPipelines.get(context, variant, [&] {
//       return vk::Pipeline::graphics(context, "forward.vert", "forward.frag", descOf(variant));
//   });
//
// (Not VkPipelineCache, which caches the driver's compilation across variants and runs:
// vk/pipeline_cache_file.h; every pipeline goes through both.)

#include "core/worker_pool.h"
#include "vk/pipeline.h"

#include <cstddef>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <utility>

namespace candela::vk {

template <class Key>
class PipelineCache {
public:
    PipelineCache() = default;
    PipelineCache(const PipelineCache&) = delete;
    PipelineCache& operator=(const PipelineCache&) = delete;
    // Drops the builds nobody started and waits for those running (they may use the context).
    ~PipelineCache() { cancelPending(); }

    // The pipeline of `key`: made by `make()` (returning a Pipeline) on the first call with that key;
    // when a build was prepared, that build's result (run here if no worker has started it, else
    // waited for; its exception, if it threw, is thrown here and the key stays unbuilt). On later
    // calls refreshed (rebuilt if one of its shaders was replaced; if the rebuild fails the old
    // pipeline stays, see Pipeline::refresh). The reference stays valid while the cache lives.
    template <class Make>
    const Pipeline& get(Context& context, const Key& key, Make&& make) {
        auto it = mPipelines.find(key);
        if (it == mPipelines.end()) {
            if (auto pending = mPending.find(key); pending != mPending.end()) {
                const std::shared_ptr<Build> build = std::move(pending->second);
                mPending.erase(pending);
                WorkerPool::runOrWait(build->job);
                if (build->result->error) std::rethrow_exception(build->result->error);
                it = mPipelines.emplace(key, std::move(*build->result->pipeline)).first;
            } else {
                return mPipelines.emplace(key, std::forward<Make>(make)()).first->second;
            }
        }
        it->second.refresh(context);
        return it->second;
    }

    // Queues the build of `key`'s pipeline on `workers` unless it is built or queued. `make` runs
    // on a worker thread (or in get(), whichever comes first): it must own what it uses (capture
    // by value) and build through Pipeline::compute/graphics. Preconditions: `workers` outlives
    // this cache or finish()/the destructor runs first; called from the thread that calls get().
    template <class Make>
    void prepare(WorkerPool& workers, const Key& key, Make make, WorkerPool::Priority priority) {
        if (mPipelines.count(key) || mPending.count(key)) return;
        auto build = std::make_shared<Build>();
        build->job = workers.submit(
            [result = build->result, make = std::move(make)]() mutable {
                try {
                    result->pipeline.emplace(make());
                } catch (...) {
                    result->error = std::current_exception();
                }
            },
            priority);
        mPending.emplace(key, std::move(build));
    }

    // Waits for every queued build (running the ones nobody started here) and keeps the results;
    // a build that threw is dropped (get() builds it again and throws then).
    void finish() {
        for (auto& [key, build] : mPending) {
            WorkerPool::runOrWait(build->job);
            if (!build->result->error) mPipelines.emplace(key, std::move(*build->result->pipeline));
        }
        mPending.clear();
    }

    // Variants built so far (queued builds not counted until get() or finish() takes them).
    size_t size() const { return mPipelines.size(); }
    // Queued builds not yet taken; of those, how many have finished on a worker.
    size_t pending() const { return mPending.size(); }
    size_t pendingFinished() const {
        size_t n = 0;
        for (const auto& [key, build] : mPending) n += WorkerPool::finished(build->job);
        return n;
    }

private:
    // Where a build leaves its pipeline or its exception (shared by the job and the cache).
    struct Result {
        std::optional<Pipeline> pipeline;
        std::exception_ptr error;
    };
    // A queued build. The job holds only the Result, so nothing refers back to the job.
    struct Build {
        WorkerPool::JobHandle job;
        std::shared_ptr<Result> result = std::make_shared<Result>();
    };

    void cancelPending() {
        for (auto& [key, build] : mPending) WorkerPool::cancel(build->job);
        mPending.clear();
    }

    std::map<Key, Pipeline> mPipelines;
    std::map<Key, std::shared_ptr<Build>> mPending;
};

}  // namespace candela::vk
