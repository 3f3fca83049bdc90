// libFuzzer entry point: the Radiance .hdr reader (header, resolution line, flat/RLE/old-RLE scanlines).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    candela::fuzz::fuzzHdr(data, size);
    return 0;
}
