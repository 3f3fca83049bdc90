// libFuzzer entry point: the KTX2 reader (container, BasisLZ/ETC1S, UASTC with Zstandard).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    candela::fuzz::fuzzKtx2(data, size);
    return 0;
}
