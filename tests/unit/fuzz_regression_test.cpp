// Replays every input the fuzzers ever failed on (tests/fuzz/regressions/TARGET/*) through the same
// target functions the libFuzzer harnesses call (tests/fuzz/fuzz_targets.h): each must load or be
// refused with a UserError, keep the loaded data's invariants, and — in the asan preset — raise
// no sanitizer report. New findings are added as files; see docs/fuzzing.md.
#include "fuzz_targets.h"

#include "core/check.h"
#include "scene/exr_reader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <vector>

namespace candela::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kRegressions = CANDELA_FUZZ_REGRESSIONS;

std::vector<fs::path> inputs(const std::string& target) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(kRegressions / target))
        if (entry.is_regular_file() && entry.path().filename() != ".keep") files.push_back(entry.path());
    return files;
}

std::vector<uint8_t> bytesOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(FuzzRegressions, GltfInputsLoadOrFailCleanly) {
    for (const fs::path& file : inputs("gltf")) {
        SCOPED_TRACE(file.string());
        const std::vector<uint8_t> bytes = bytesOf(file);
        fuzzGltf(bytes.data(), bytes.size(), kRegressions.parent_path() / "uri-folder");
    }
}

TEST(FuzzRegressions, HdrInputsLoadOrFailCleanly) {
    for (const fs::path& file : inputs("hdr")) {
        SCOPED_TRACE(file.string());
        const std::vector<uint8_t> bytes = bytesOf(file);
        fuzzHdr(bytes.data(), bytes.size());
    }
}

TEST(FuzzRegressions, ExrInputsLoadOrFailCleanly) {
    for (const fs::path& file : inputs("exr")) {
        SCOPED_TRACE(file.string());
        const std::vector<uint8_t> bytes = bytesOf(file);
        fuzzExr(bytes.data(), bytes.size());
    }
}

// The finding behind checkAttributeLayout (docs/fuzzing.md, finding 8): OpenEXRCore accepts this
// header, OpenEXR's C++ library would allocate the 1.8 GB its mangled attribute claims. Refused first.
TEST(FuzzRegressions, ExrAttributeBeyondTheFileIsRefusedBeforeTheCppLibraryReadsIt) {
    const std::vector<uint8_t> bytes = bytesOf(kRegressions / "exr" / "attribute-size-past-end.exr");
    try {
        scene::decodeExr(bytes, "a.exr", {});
        ADD_FAILURE() << "loaded";
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()), std::string("a.exr: invalid EXR header: attribute 'screenWiv/1") + std::string(3, '?') + "' claims 1851877475 bytes, 385 remain");
    }
}

}  // namespace
}  // namespace candela::fuzz
