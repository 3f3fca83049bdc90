// libFuzzer entry point: the levels-of-detail cache file (geometry/lod_cache_file.h), the chains
// and frame counts earlier runs left in the cache folder.
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    candela::fuzz::fuzzLodCache(data, size);
    return 0;
}
