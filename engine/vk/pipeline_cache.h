#pragma once
// PipelineCache<Key>: the pipeline variants of one pass (specialization constants, target formats),
// each built on its first use and kept. A later use of a variant refreshes it, so a shader replaced
// at run time (hot reload) rebuilds every variant of it at that variant's next use, while frames
// in flight keep the old pipeline (deferred deletion). Every pass with variants keeps one:
//
//   vk::PipelineCache<Variant> mPipelines;  // Variant: any type with operator<
//   const vk::Pipeline& p = mPipelines.get(context, variant, [&] {
//       return vk::Pipeline::graphics(context, "forward.vert", "forward.frag", descOf(variant));
//   });

#include "vk/pipeline.h"

#include <cstddef>
#include <map>
#include <utility>

namespace candela::vk {

template <class Key>
class PipelineCache {
public:
    // The pipeline of `key`: made by `make()` (returning a Pipeline) on the first call with that key;
    // on later calls refreshed (rebuilt if one of its shaders was replaced; if the rebuild fails the
    // old pipeline stays, see Pipeline::refresh). The reference stays valid while the cache lives.
    template <class Make>
    const Pipeline& get(Context& context, const Key& key, Make&& make) {
        auto it = mPipelines.find(key);
        if (it == mPipelines.end()) return mPipelines.emplace(key, std::forward<Make>(make)()).first->second;
        it->second.refresh(context);
        return it->second;
    }

    // Variants built so far.
    size_t size() const { return mPipelines.size(); }

private:
    std::map<Key, Pipeline> mPipelines;
};

}  // namespace candela::vk
