// What the on-disk caches share (core/cache_files.h): the user's cache folder from the XDG
// variables, and atomic writes (complete or absent, no temporary left behind, errors naming the file).
#include "core/cache_files.h"
#include "core/errors.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace candela {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(UserCacheFolder, FollowsTheXdgBaseDirectorySpecification) {
    EXPECT_EQ(userCacheFolder("/xdg/cache", "/home/u"), fs::path("/xdg/cache/candela"));
    EXPECT_EQ(userCacheFolder(nullptr, "/home/u"), fs::path("/home/u/.cache/candela"));
    EXPECT_EQ(userCacheFolder("", "/home/u"), fs::path("/home/u/.cache/candela"));
    // A relative XDG_CACHE_HOME is invalid: ignored.
    EXPECT_EQ(userCacheFolder("relative/cache", "/home/u"), fs::path("/home/u/.cache/candela"));
    EXPECT_EQ(userCacheFolder(nullptr, nullptr), fs::path());
    EXPECT_EQ(userCacheFolder(nullptr, ""), fs::path());
    EXPECT_EQ(userCacheFolder("/xdg", nullptr), fs::path("/xdg/candela"));
}

TEST(PipelineCacheFolder, OffIsNoneEmptyIsTheUsersAnythingElseThatFolder) {
    EXPECT_TRUE(pipelineCacheFolder("off").empty());
    EXPECT_EQ(pipelineCacheFolder(""), userCacheFolder());
    EXPECT_EQ(pipelineCacheFolder("some/folder"), fs::path("some/folder"));
}

TEST(AtomicWrite, WritesReplacesAndLeavesNoTemporary) {
    test::TempDir dir("candela_atomic");
    const fs::path path = dir / "sub" / "file.bin";
    writeFileAtomically(path, [](std::ostream& out) { out << "first"; });
    EXPECT_EQ(readText(path), "first");
    writeFileAtomically(path, [](std::ostream& out) { out << "second, longer"; });
    EXPECT_EQ(readText(path), "second, longer");
    size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(path.parent_path())) ++files;
    EXPECT_EQ(files, 1u);
}

TEST(AtomicWrite, AFailingWriterLeavesTheOldFileAndNoTemporary) {
    test::TempDir dir("candela_atomic");
    const fs::path path = dir / "file.bin";
    writeFileAtomically(path, [](std::ostream& out) { out << "old"; });
    EXPECT_THROW(writeFileAtomically(path,
                                     [](std::ostream& out) {
                                         out << "partial";
                                         throw std::runtime_error("writer failed");
                                     }),
                 std::runtime_error);
    EXPECT_EQ(readText(path), "old");
    size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path())) ++files;
    EXPECT_EQ(files, 1u);
}

TEST(AtomicWrite, UncreatableFolderIsAUserErrorNamingTheFile) {
    test::TempDir dir("candela_atomic");
    std::ofstream(dir / "plain") << "x";
    const fs::path path = dir / "plain" / "file.bin";  // its folder would be a file
    try {
        writeFileAtomically(path, [](std::ostream& out) { out << "x"; });
        FAIL() << "no error";
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": cannot create the directory", 0), 0u) << e.what();
    }
}

}  // namespace
}  // namespace candela
