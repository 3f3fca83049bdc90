// libFuzzer entry point: the glTF/GLB loader (tinygltf's parser and all of Candela's loading code:
// GLB container, URIs, accessors, sparse, indices, topology conversion, images, materials, nodes).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    candela::fuzz::fuzzGltf(data, size, CANDELA_FUZZ_URI_FOLDER);
    return 0;
}
