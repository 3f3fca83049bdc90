// What the on-disk caches share (core/cache_files.h): the user's cache folder from the XDG
// variables, and atomic writes (complete or absent, no temporary left behind, errors naming the file).
#include "core/cache_files.h"
#include "core/errors.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>

namespace candela {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The names of the files in `dir`, sorted.
std::vector<std::string> fileNames(const test::TempDir& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir.path())) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    ASSERT_TRUE(out.good()) << path;
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

TEST(LodCacheFolder, OffIsNoneEmptyIsTheUsersLodFolderAnythingElseThatFolder) {
    EXPECT_TRUE(lodCacheFolder("off").empty());
    const fs::path user = userCacheFolder();
    EXPECT_EQ(lodCacheFolder(""), user.empty() ? fs::path() : user / "lod");
    EXPECT_EQ(lodCacheFolder("some/folder"), fs::path("some/folder"));
}

TEST(WordHash64, ValueIsFixedAndEveryByteAndTheLengthCount) {
    // Part of cache file names: the value must not change between versions (pinned).
    EXPECT_EQ(hex16(wordHash64(0, "", 0)), "0000000000000000");
    const std::string text = "levels of detail, keyed by content";
    const uint64_t h = wordHash64(0, text.data(), text.size());
    EXPECT_EQ(hex16(h), "2fc7718f3fbb869b");
    for (size_t i = 0; i < text.size(); ++i)
        for (int bit = 0; bit < 8; ++bit) {
            std::string flipped = text;
            flipped[i] = char(flipped[i] ^ (1 << bit));
            EXPECT_NE(wordHash64(0, flipped.data(), flipped.size()), h) << "byte " << i << " bit " << bit;
        }
    // Trailing zero bytes are not padding: the length is part of the hash.
    const std::string padded = text + std::string(3, '\0');
    EXPECT_NE(wordHash64(0, padded.data(), padded.size()), h);
    // Continuing from a hash differs from starting anew; the seed matters.
    EXPECT_NE(wordHash64(h, text.data(), text.size()), h);
    EXPECT_NE(wordHash64(1, text.data(), text.size()), h);
}

TEST(WordHasher, AnySplitOfTheBytesHashesAsOneCall) {
    std::string text;
    for (int i = 0; i < 61; ++i) text.push_back(char(i * 37 + 11));
    for (uint64_t seed : {uint64_t(0), uint64_t(0x1234)}) {
        for (size_t n = 0; n <= text.size(); ++n) {
            const uint64_t whole = wordHash64(seed, text.data(), n);
            // Every split into two pieces, and the bytes one at a time.
            for (size_t cut = 0; cut <= n; ++cut) {
                WordHasher hasher(seed);
                hasher.update(text.data(), cut);
                hasher.update(text.data() + cut, n - cut);
                ASSERT_EQ(hasher.value(), whole) << "length " << n << " cut at " << cut;
            }
            WordHasher bytewise(seed);
            for (size_t i = 0; i < n; ++i) bytewise.update(text.data() + i, 1);
            ASSERT_EQ(bytewise.value(), whole) << "length " << n << " byte by byte";
        }
    }
    // value() does not end the stream.
    WordHasher hasher;
    hasher.update(text.data(), 5);
    EXPECT_EQ(hasher.value(), wordHash64(0, text.data(), 5));
    hasher.update(text.data() + 5, 20);
    EXPECT_EQ(hasher.value(), wordHash64(0, text.data(), 25));
}

TEST(CacheEviction, RemovesTheLeastRecentlyUsedOfItsKindBeyondTheCap) {
    test::TempDir dir;
    const auto file = [&](const std::string& name) { return dir.path() / (name + ".cibl"); };
    const auto at = [](int secondsAgo) { return fs::file_time_type::clock::now() - std::chrono::seconds(secondsAgo); };
    // Four files of 100 bytes written 40, 30, 20 and 10 s ago, and a file of another kind.
    for (int i = 0; i < 4; ++i) {
        writeText(file("map" + std::to_string(i)), std::string(100, char(i)));
        fs::last_write_time(file("map" + std::to_string(i)), at(40 - 10 * i));
    }
    writeText(dir.path() / "notes.txt", std::string(1000, 0));
    // map0, the oldest, was read just now: it is the most recently used.
    touchCacheFile(file("map0"));
    // Under the cap: nothing goes.
    EXPECT_TRUE(evictCacheFiles(dir.path(), ".cibl", 400, file("map3")).empty());
    // 250 bytes: the two least recently used (map1, map2) go; the other file is not the cache's.
    const std::vector<fs::path> removed = evictCacheFiles(dir.path(), ".cibl", 250, file("map3"));
    EXPECT_EQ(removed, (std::vector<fs::path>{file("map1"), file("map2")}));
    EXPECT_EQ(fileNames(dir), (std::vector<std::string>{"map0.cibl", "map3.cibl", "notes.txt"}));
    // The file just written stays even alone over the cap.
    EXPECT_EQ(evictCacheFiles(dir.path(), ".cibl", 50, file("map3")), std::vector<fs::path>{file("map0")});
    EXPECT_EQ(fileNames(dir), (std::vector<std::string>{"map3.cibl", "notes.txt"}));
    // A folder that is not there: nothing to do, no error.
    EXPECT_TRUE(evictCacheFiles(dir.path() / "none", ".cibl", 0, {}).empty());
    touchCacheFile(dir.path() / "none" / "x.cibl");
}

}  // namespace
}  // namespace candela
