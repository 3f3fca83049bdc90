// Replays every input the fuzzers ever failed on (tests/fuzz/regressions/TARGET/*) through the same
// target functions the libFuzzer harnesses call (tests/fuzz/fuzz_targets.h): each must load or be
// refused with a UserError, keep the loaded data's invariants, and — in the asan preset — raise
// no sanitizer report. New findings are added as files; see docs/fuzzing.md.
#include "fuzz_targets.h"

#include "assets/exr_reader.h"
#include "core/errors.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <vector>

namespace candela::assets::test::fuzz_regression_test {
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
        fuzz::fuzzGltf(bytes.data(), bytes.size(), kRegressions.parent_path() / "uri-folder");
    }
}

TEST(FuzzRegressions, Ktx2InputsLoadOrFailCleanly) {
    for (const fs::path& file : inputs("ktx2")) {
        SCOPED_TRACE(file.string());
        const std::vector<uint8_t> bytes = bytesOf(file);
        fuzz::fuzzKtx2(bytes.data(), bytes.size());
    }
}

TEST(FuzzRegressions, WebpInputsLoadOrFailCleanly) {
    for (const fs::path& file : inputs("webp")) {
        SCOPED_TRACE(file.string());
        const std::vector<uint8_t> bytes = bytesOf(file);
        fuzz::fuzzWebp(bytes.data(), bytes.size());
    }
}

TEST(FuzzRegressions, HdrInputsLoadOrFailCleanly) {
    for (const fs::path& file : inputs("hdr")) {
        SCOPED_TRACE(file.string());
        const std::vector<uint8_t> bytes = bytesOf(file);
        fuzz::fuzzHdr(bytes.data(), bytes.size());
    }
}

TEST(FuzzRegressions, ExrInputsLoadOrFailCleanly) {
    for (const fs::path& file : inputs("exr")) {
        SCOPED_TRACE(file.string());
        const std::vector<uint8_t> bytes = bytesOf(file);
        fuzz::fuzzExr(bytes.data(), bytes.size());
    }
}

// Findings 8–10 (docs/fuzzing.md): headers OpenEXRCore's lenient mode accepted with defaults
// while OpenEXR's C++ library, reading on, would have sized buffers of 0.8 to 1.9 GB from them.
// OpenEXRCore's strict validation refuses each before the C++ library reads anything.
TEST(FuzzRegressions, ExrHeadersOnlyALenientParseAcceptsAreRefused) {
    const std::pair<const char*, std::string> cases[] = {
        {"attribute-size-past-end.exr", "Invalid empty string encountered parsing attribute type for attribute"},
        {"box2i-size-mismatch.exr", "Attribute 'dataWindow': Invalid size 35 (exp 'box2i' size 4 * 4 (16))"},
        {"empty-attribute-type.exr", "Invalid empty string encountered parsing attribute type for attribute 'c '"}};
    for (const auto& [file, fragment] : cases) {
        const std::vector<uint8_t> bytes = bytesOf(kRegressions / "exr" / file);
        try {
            assets::decodeExr(bytes, "a.exr", {});
            ADD_FAILURE() << file << " loaded";
        } catch (const UserError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind("a.exr: invalid EXR header: ", 0), 0u) << message;
            EXPECT_NE(message.find(fragment), std::string::npos) << message;
        }
    }
}

}  // namespace
}  // namespace candela::assets::test::fuzz_regression_test
