// libFuzzer entry point: the OpenEXR reader (OpenEXRCore's header parsing and decompression,
// Candela's part and channel choice, window handling and size checks).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    candela::fuzz::fuzzExr(data, size);
    return 0;
}
