// libFuzzer entry point: the check --resume makes of a per-pixel output's NumPy .npy file (its
// header's shape and type against the bytes that follow).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    candela::fuzz::fuzzNpy(data, size);
    return 0;
}
