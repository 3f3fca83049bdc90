// libFuzzer entry point: WebP images through libwebp behind Candela's checks.
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    candela::fuzz::fuzzWebp(data, size);
    return 0;
}
