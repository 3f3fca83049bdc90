// The scenes of a `candela render` run (scene_batch.h): inputs expanded in order, shards that
// partition, output patterns. No device: files are listed, not loaded.

#include "scene_batch.h"

#include "temp_dir.h"

#include <gtest/gtest.h>

#include <map>

#include <fstream>
#include <set>

namespace candela::app {
namespace {

using test::TempDir;
namespace fs = std::filesystem;

void touch(const std::filesystem::path& file) {
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << "{}";
}

std::vector<std::string> names(const std::vector<SceneInput>& scenes) {
    std::vector<std::string> out;
    for (const SceneInput& s : scenes) out.push_back(s.path);
    return out;
}

TEST(SceneBatch, FoldersAreWalkedInSortedOrderForGltfAndGlbOnly) {
    TempDir dir;
    touch(dir / "lib/b/Box.glb");
    touch(dir / "lib/a/Box.gltf");
    touch(dir / "lib/a/Box.bin");
    touch(dir / "lib/a/texture.png");
    touch(dir / "lib/C.GLB");
    const std::vector<SceneInput> scenes = expandSceneInputs({(dir / "lib").string()});
    EXPECT_EQ(names(scenes), (std::vector<std::string>{"C", "a/Box", "b/Box"}));
    EXPECT_EQ(scenes[1].name, "Box");
    EXPECT_EQ(scenes[1].file, dir / "lib/a/Box.gltf");
}

TEST(SceneBatch, FilesListsAndFoldersKeepTheirOrderAndAFileReachedTwiceRendersOnce) {
    TempDir dir;
    touch(dir / "one.glb");
    touch(dir / "lib/two.gltf");
    touch(dir / "lib/three.glb");
    std::ofstream(dir / "list.txt") << "# a comment\n\n  " << (dir / "lib/two.gltf").string() << "  \n"
                                    << (dir / "missing.glb").string() << "\n";
    const std::vector<SceneInput> scenes =
        expandSceneInputs({(dir / "one.glb").string(), "@" + (dir / "list.txt").string(), (dir / "lib").string()});
    ASSERT_EQ(scenes.size(), 4u);
    EXPECT_EQ(scenes[0].name, "one");
    EXPECT_EQ(scenes[1].name, "two");
    // A path that does not exist stays a scene: its load fails and is reported with the others.
    EXPECT_EQ(scenes[2].name, "missing");
    EXPECT_EQ(scenes[3].name, "three");  // lib/two.gltf came through the list already
}

TEST(SceneBatch, PathOfAFileNamedDirectlyStaysInsideTheOutputFolder) {
    EXPECT_EQ(expandSceneInputs({"../models/./Box.glb"})[0].path, "models/Box");
    EXPECT_EQ(expandSceneInputs({"/abs/models/Box.glb"})[0].path, "abs/models/Box");
}

TEST(SceneBatch, BadListsAndEmptyFoldersAreErrors) {
    TempDir dir;
    std::filesystem::create_directories(dir / "empty");
    EXPECT_THROW(expandSceneInputs({(dir / "empty").string()}), UserError);
    EXPECT_THROW(expandSceneInputs({"@" + (dir / "no-list.txt").string()}), UserError);
    std::ofstream(dir / "nested.txt") << "@other.txt\n";
    EXPECT_THROW(expandSceneInputs({"@" + (dir / "nested.txt").string()}), UserError);
}

TEST(SceneBatch, ListsSkipCommentsBlankLinesAndSpaces) {
    EXPECT_EQ(parseSceneList("# thumbnails\n\n  models/a b.glb \t\r\n#x.glb\nlib/\nlast.gltf", "l.txt"),
              (std::vector<std::string>{"models/a b.glb", "lib/", "last.gltf"}));
    EXPECT_TRUE(parseSceneList("", "l.txt").empty());
    try {
        parseSceneList("a.glb\n @b.txt\n", "l.txt");
        FAIL() << "a list inside a list";
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()), "@l.txt line 2: a list of scenes cannot name another list (@b.txt)");
    }
    EXPECT_THROW(parseSceneList(std::string("a\0b.glb\n", 8), "l.txt"), UserError);
}

// Every input the list fuzzer (tests/fuzz/fuzz_scene_list.cpp) ever failed on reads or fails
// cleanly (none so far: the folder holds only .keep).
TEST(SceneBatch, FuzzRegressionsReadOrFailCleanly) {
    for (const auto& entry : fs::directory_iterator(fs::path(CANDELA_FUZZ_REGRESSIONS) / "scene_list")) {
        std::ifstream in(entry.path(), std::ios::binary);
        const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        try {
            for (const std::string& line : parseSceneList(text, "fuzz.txt")) EXPECT_FALSE(line.empty());
        } catch (const UserError&) {
        }
    }
}

TEST(SceneBatch, ShardsPartitionTheList) {
    std::vector<SceneInput> scenes;
    for (int i = 0; i < 85; ++i) scenes.push_back({"s" + std::to_string(i) + ".glb", "s" + std::to_string(i), "s" + std::to_string(i)});
    for (uint32_t count : {1u, 2u, 4u, 7u, 85u, 100u}) {
        std::multiset<std::string> seen;
        for (uint32_t index = 1; index <= count; ++index) {
            const std::vector<SceneInput> share = shardOf(scenes, {index, count});
            EXPECT_LE(share.size(), (scenes.size() + count - 1) / count);
            for (const SceneInput& s : share) seen.insert(s.name);
        }
        EXPECT_EQ(seen.size(), scenes.size()) << count << " shards";
        for (const SceneInput& s : scenes) EXPECT_EQ(seen.count(s.name), 1u) << s.name << " in " << count << " shards";
    }
    EXPECT_EQ(shardOf(scenes, {2, 4})[1].name, "s5");  // every 4th from the 2nd
}

TEST(SceneBatch, ShardFlagTakesIOverN) {
    EXPECT_EQ(parseShard("--shard", "3/4"), (Shard{3, 4}));
    EXPECT_EQ(parseShard("--shard", "1/1"), (Shard{1, 1}));
    for (const char* bad : {"0/4", "5/4", "4", "/4", "1/", "a/b", "1/0", "-1/4", "1/4/2"})
        EXPECT_THROW(parseShard("--shard", bad), UserError) << bad;
}

// --shard auto: the job runners' environments, as a table.
TEST(SceneBatch, ShardAutoReadsTheJobArraysEnvironment) {
    const auto from = [](std::map<std::string, std::string> table) {
        return [table = std::move(table)](const char* name) -> const char* {
            const auto it = table.find(name);
            return it == table.end() ? nullptr : it->second.c_str();
        };
    };
    // Slurm, --array=0-3 and --array=1-4 (ids from SLURM_ARRAY_TASK_MIN).
    EXPECT_EQ(parseShard("--shard", "auto", from({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_COUNT", "4"}})),
              (Shard{3, 4}));
    EXPECT_EQ(parseShard("--shard", "auto", from({{"SLURM_ARRAY_TASK_ID", "4"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}})),
              (Shard{4, 4}));
    // Kubernetes: the index from 0, the count given.
    EXPECT_EQ(parseShard("--shard", "auto/8", from({{"JOB_COMPLETION_INDEX", "0"}})), (Shard{1, 8}));
    EXPECT_EQ(parseShard("--shard", "auto/8", from({{"JOB_COMPLETION_INDEX", "7"}})), (Shard{8, 8}));
    // GitLab: from 1.
    EXPECT_EQ(parseShard("--shard", "auto", from({{"CI_NODE_INDEX", "2"}, {"CI_NODE_TOTAL", "3"}})), (Shard{2, 3}));
    // A count given wins over the environment's.
    EXPECT_EQ(parseShard("--shard", "auto/2", from({{"CI_NODE_INDEX", "2"}, {"CI_NODE_TOTAL", "3"}})), (Shard{2, 2}));
    const auto fails = [&](const std::string& value, std::map<std::string, std::string> table, const std::string& says) {
        try {
            parseShard("--shard", value, from(std::move(table)));
            ADD_FAILURE() << value << ": no error";
        } catch (const UserError& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
        }
    };
    fails("auto", {}, "none of SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX and CI_NODE_INDEX is set");
    fails("auto", {{"JOB_COMPLETION_INDEX", "3"}}, "give it: --shard auto/N");
    fails("auto/4", {{"JOB_COMPLETION_INDEX", "4"}}, "gives shard 5 of 4");
    fails("auto/4", {{"JOB_COMPLETION_INDEX", "x"}}, "JOB_COMPLETION_INDEX is 'x', not a number");
    fails("auto/0", {{"JOB_COMPLETION_INDEX", "0"}}, "auto/N with N >= 1");
    fails("auto", {{"SLURM_ARRAY_TASK_ID", "7"}, {"SLURM_ARRAY_TASK_COUNT", "3"}}, "gives shard 8 of 3");
}

TEST(SceneBatch, OutPatternsNameEachImage) {
    const OutputFields fields{"Box", "lib/Box", "red", std::nullopt};
    EXPECT_EQ(expandOutPattern("thumbs/{name}.png", fields), "thumbs/Box.png");
    EXPECT_EQ(expandOutPattern("{path}-{variant}.exr", fields), "lib/Box-red.exr");
    OutputFields frame = fields;
    frame.frame = 7;
    EXPECT_EQ(expandOutPattern("{name}/{frame}.png", frame), "Box/0007.png");
    EXPECT_EQ(expandOutPattern("{name}_%03d.png", frame), "Box_007.png");
    OutputFields percent = frame;
    percent.name = "100%";
    EXPECT_EQ(expandOutPattern("{name}_%d.png", percent), "100%_7.png");  // a name's % is not a field
    EXPECT_EQ(expandOutPattern("plain.png", fields), "plain.png");
    EXPECT_TRUE(usesField("a/{variant}.png", "variant"));
    EXPECT_FALSE(usesField("a/{name}.png", "variant"));
    EXPECT_NO_THROW(checkOutPattern("{name}{path}{variant}{frame}.png"));
    EXPECT_THROW(checkOutPattern("{scene}.png"), UserError);
    EXPECT_THROW(checkOutPattern("{name.png"), UserError);
}

}  // namespace
}  // namespace candela::app
