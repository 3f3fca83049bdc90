// libFuzzer entry point: the OpenEXR reader (tinyexr's header and decompression, Candela's channel
// selection and size checks).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    candela::fuzz::fuzzExr(data, size);
    return 0;
}
