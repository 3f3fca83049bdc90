// Whole and partial image files (assets/image_file.h): what the writers write is complete, and
// every shorter prefix of it is not (what a killed writer would have left before writes became
// atomic); the writers leave no temporary file; removeStaleTemporaries removes only a writer's.

#include "temp_dir.h"
#include "assets/image_file.h"
#include "assets/output_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <vector>

namespace candela::assets {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& file, const std::string& bytes) { std::ofstream(file, std::ios::binary) << bytes; }

TEST(ImageFileComplete, WhatTheWritersWriteIsCompleteAndNoPrefixOfItIs) {
    const TempDir dir("candela_image_complete");
    const uint32_t width = 7, height = 5;
    std::vector<uint8_t> rgba8(width * height * 4);
    std::vector<float> rgba32(width * height * 4);
    for (size_t i = 0; i < rgba8.size(); ++i) {
        rgba8[i] = uint8_t(i * 37);
        rgba32[i] = float(i) * 0.01f;
    }
    writePng(dir.path() / "a.png", width, height, rgba8);
    writeExr(dir.path() / "a.exr", width, height, rgba32);
    writePfm(dir.path() / "a.pfm", width, height, rgba32);
    // The per-pixel outputs' files: a NumPy array, and an EXR of float and uint channels.
    std::vector<float> depth(width * height, 2.5f);
    std::vector<uint32_t> ids(width * height, 0xFFFFFFFFu);
    const OutputPlane planes[] = {{.name = "depth", .channels = {"Z"}, .floats = depth},
                                  {.name = "node_id", .channels = {"node_id.id"}, .integer = true, .ids = ids}};
    writeNpy(dir.path() / "a.npy", width, height, planes[1]);
    writeOutputsExr(dir.path() / "b.exr", width, height, rgba32, planes);
    EXPECT_EQ(readFile(dir.path() / "a.npy").size(), 128u + width * height * 4);
    for (const char* name : {"a.png", "a.exr", "a.pfm", "a.npy", "b.exr"}) {
        const fs::path file = dir.path() / name;
        ASSERT_TRUE(imageFileComplete(file)) << name;
        const std::string bytes = readFile(file);
        const fs::path cut = dir.path() / (std::string("cut") + fs::path(name).extension().string());
        for (size_t length = 0; length < bytes.size(); length += length < 64 ? 1 : 7) {
            writeBytes(cut, bytes.substr(0, length));
            EXPECT_FALSE(imageFileComplete(cut)) << name << " cut to " << length << " of " << bytes.size() << " bytes";
        }
        writeBytes(cut, bytes.substr(0, bytes.size() - 1));
        EXPECT_FALSE(imageFileComplete(cut)) << name << " without its last byte";
    }
    EXPECT_FALSE(imageFileComplete(dir.path() / "missing.png"));
    EXPECT_FALSE(imageFileComplete(dir.path()));  // a folder
    writeBytes(dir.path() / "text.png", "not an image at all, but long enough to have an end");
    EXPECT_FALSE(imageFileComplete(dir.path() / "text.png"));
    // The writers leave nothing but their files.
    for (const auto& entry : fs::directory_iterator(dir.path()))
        EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
}

TEST(ImageFileComplete, OnlyAWritersTemporariesAreRemoved) {
    const TempDir dir("candela_image_stale");
    const fs::path out = dir.path() / "x.png";
    for (const char* name : {"x.png.tmp-0123456789abcdef", "x.png.tmp-fedcba9876543210", "x.png.tmp-short", "x.png.tmp-0123456789ABCDEF",
                             "y.png.tmp-0123456789abcdef", "x.png"})
        writeBytes(dir.path() / name, "x");
    EXPECT_EQ(removeStaleTemporaries(out), 2u);
    for (const char* kept : {"x.png.tmp-short", "x.png.tmp-0123456789ABCDEF", "y.png.tmp-0123456789abcdef", "x.png"})
        EXPECT_TRUE(fs::exists(dir.path() / kept)) << kept;
    EXPECT_EQ(removeStaleTemporaries(dir.path() / "none/z.png"), 0u);  // no folder: nothing, no error
}

}  // namespace
}  // namespace candela::assets
