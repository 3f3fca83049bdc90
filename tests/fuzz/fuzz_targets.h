#pragma once
// The fuzz targets as plain functions, shared by the libFuzzer entry points (fuzz_*.cpp,
// built by the fuzz preset) and by the regression test that replays every input the fuzzers ever
// crashed on (tests/unit/assets/fuzz_regression_test.cpp, in the ordinary and the sanitizer builds).
//
// Each feeds one input to a reader and returns normally when the reader either accepted it or
// threw candela::UserError. Anything else is a defect the fuzzer must report: another exception
// escapes (libFuzzer reports it as a crash), a sanitizer fires, or the result breaks an invariant
// the rest of Candela relies on (checked here; a violation aborts with a message on stderr).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "geometry/lod_cache_file.h"

namespace candela::fuzz {

// loadGltfFromMemory on `data` as if it were FOLDER/fuzz.gltf, where FOLDER is `uriFolder`
// (relative URIs resolve there; the fuzzers point it at a folder holding one buffer and one PNG).
// Checks the loaded scene: every index names a vertex, every draw's range and material exist,
// texture references name existing images and samplers, image pixel arrays match their size, and
// every vertex, transform, light and camera value is finite.
void fuzzGltf(const uint8_t* data, size_t size, const std::filesystem::path& uriFolder);

// decodeHdr then sanitizeEnvironment; checks the size and that every texel is finite and ≥ 0.
void fuzzHdr(const uint8_t* data, size_t size);

// decodeExr then sanitizeEnvironment; the same checks.
void fuzzExr(const uint8_t* data, size_t size);

// textures::decodeKtx2 (the container, BasisLZ/ETC1S and UASTC with Zstandard); checks that level 0
// has the header's size, each further level half the previous one, and every level's byte count.
void fuzzKtx2(const uint8_t* data, size_t size);

// textures::decodeWebp (libwebp behind Candela's checks); the same checks for its single level.
void fuzzWebp(const uint8_t* data, size_t size);

// assets::npyComplete (a per-pixel output's .npy file, --resume's check); checks that a file it
// calls complete is as long as its header's 4-byte values say.
void fuzzNpy(const uint8_t* data, size_t size);

// geometry::parseLodCache (the levels-of-detail cache file) against the key and meshes below (the
// seeds are encoded for them); checks that accepted chains are what attachLevelsOfDetail relies
// on: one per mesh, each level fewer whole triangles than the one before, indices within the mesh.
void fuzzLodCache(const uint8_t* data, size_t size);
extern const geometry::LodCacheKey kFuzzLodCacheKey;
extern const std::vector<geometry::LodCacheMesh> kFuzzLodCacheMeshes;

}  // namespace candela::fuzz
