#pragma once
// The folders the tests read and write, fixed when CMake configures the tree (compile definitions
// of the same names) and overridable at run time by an environment variable of the same name: a
// test binary copied to another machine (tools/gpu-check.sh runs the GPU tests from a bundle) finds
// the approved images, the test data and the sample models where that machine keeps them.
// A function is declared only where its CMake target defines the path.

#include <cstdlib>
#include <filesystem>

namespace candela::test {

// `variable`'s value from the environment when set and not empty, else `configured`.
inline std::filesystem::path testPath(const char* variable, const char* configured) {
    const char* value = std::getenv(variable);
    return value && *value ? std::filesystem::path(value) : std::filesystem::path(configured);
}

#ifdef CANDELA_SHARED_ASSETS
// ../shared/assets: third-party sample models, environments, reference LUTs (may be absent).
inline std::filesystem::path sharedAssets() { return testPath("CANDELA_SHARED_ASSETS", CANDELA_SHARED_ASSETS); }
#endif
#ifdef CANDELA_GOLDEN_DIR
// tests/golden: the approved images.
inline std::filesystem::path goldenDir() { return testPath("CANDELA_GOLDEN_DIR", CANDELA_GOLDEN_DIR); }
#endif
#ifdef CANDELA_GOLDEN_OUT
// Where golden tests write renders and difference images (a folder of the build tree).
inline std::filesystem::path goldenOut() { return testPath("CANDELA_GOLDEN_OUT", CANDELA_GOLDEN_OUT); }
#endif
#ifdef CANDELA_TEST_DATA
// tests/data: committed test inputs (KTX2 files made by the reference encoder, ...).
inline std::filesystem::path testData() { return testPath("CANDELA_TEST_DATA", CANDELA_TEST_DATA); }
#endif
#ifdef CANDELA_TEST_SCENES
// assets/test-scenes: the generated stress scenes.
inline std::filesystem::path testScenes() { return testPath("CANDELA_TEST_SCENES", CANDELA_TEST_SCENES); }
#endif

}  // namespace candela::test
