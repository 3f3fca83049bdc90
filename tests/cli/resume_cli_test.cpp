// A library run killed part-way and resumed (docs/pipelines.md#resuming-a-run): every file is
// written under a temporary name and renamed into place, so SIGKILL never leaves a truncated file
// under a final name; `--resume` renders only what is missing or incomplete, removes what the
// killed run left half-written, and ends with the files of an uninterrupted run. Runs the real
// executable on lavapipe under the validation layer.

#include "gltf_test_util.h"
#include "run_candela.h"
#include "assets/image_file.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

namespace candela::test::resume_cli_test {
namespace {

namespace fs = std::filesystem;
using assets::test::GltfBuilder;
using Json = nlohmann::json;

constexpr const char* kSize = " --width 160 --height 120 --validate --quiet";

// A folder of `count` triangle scenes, each its own colour.
fs::path library(const fs::path& dir, int count) {
    fs::create_directories(dir);
    for (int i = 0; i < count; ++i) {
        GltfBuilder b;
        b.addTriangle();
        b.doc["meshes"][0]["primitives"][0]["material"] = 0;
        b.doc["materials"] = Json::array(
            {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.1 + 0.05 * i, 0.9 - 0.05 * i, 0.3, 1.0}}}}}});
        b.writeGlb(dir, "scene" + std::to_string(10 + i));
    }
    return dir;
}

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The files under `dir` (recursively) whose names end with `suffix`.
std::vector<fs::path> filesEndingWith(const fs::path& dir, const std::string& suffix) {
    std::vector<fs::path> out;
    std::error_code ec;
    for (const auto& entry : fs::recursive_directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
            out.push_back(entry.path());
    }
    return out;
}

bool isTemporary(const fs::path& file) { return file.filename().string().find(".tmp-") != std::string::npos; }

TEST(Resume, AKilledLibraryRunResumedEndsWithTheFilesOfAnUninterruptedOne) {
    const TempDir dir("candela_resume");
    const fs::path scenes = library(dir.path() / "scenes", 16);
    const Result whole = run("render " + scenes.string() + " --out " + (dir.path() / "whole/{name}.png").string() + kSize);
    ASSERT_EQ(whole.exitCode, 0) << whole.stderrText;
    ASSERT_EQ(filesEndingWith(dir.path() / "whole", ".png").size(), 16u);

    // The same run, killed once three images are written.
    const fs::path out = dir.path() / "killed";
    const std::string command = candelaExecutable() + " render " + scenes.string() + " --out " +
                                (out / "{name}.png").string() + " --report " + (out / "report.json").string() + kSize +
                                " >/dev/null 2>&1";
    const pid_t pid = fork();
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    size_t written = 0;
    while (std::chrono::steady_clock::now() < deadline) {
        written = 0;
        for (const fs::path& file : filesEndingWith(out, ".png")) written += isTemporary(file) ? 0 : 1;
        if (written >= 3) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it was killed: nothing to resume";
    // Whatever is under a final name is a whole image; the rest is missing.
    size_t complete = 0;
    for (const fs::path& file : filesEndingWith(out, ".png"))
        if (!isTemporary(file)) {
            EXPECT_TRUE(assets::imageFileComplete(file)) << file << " is under its final name but not whole";
            ++complete;
        }
    ASSERT_GE(complete, 3u);
    ASSERT_LT(complete, 16u) << "every image was written before the kill";
    EXPECT_FALSE(fs::exists(out / "report.json"));  // written at the end, not half

    const Result resumed = run("render " + scenes.string() + " --out " + (out / "{name}.png").string() + " --report " +
                               (out / "report.json").string() + " --resume" + kSize);
    ASSERT_EQ(resumed.exitCode, 0) << resumed.stderrText;
    EXPECT_NE(resumed.stdoutText.find(std::to_string(complete) + " of 16 scenes were complete already (--resume)"),
              std::string::npos)
        << resumed.stdoutText;
    for (const fs::path& reference : filesEndingWith(dir.path() / "whole", ".png")) {
        const fs::path file = out / reference.filename();
        ASSERT_TRUE(assets::imageFileComplete(file)) << file;
        EXPECT_EQ(readFile(file), readFile(reference)) << file << " differs from the uninterrupted run's";
    }
    for (const fs::path& file : filesEndingWith(out, ""))
        EXPECT_FALSE(isTemporary(file)) << file << " was left behind";
    std::ifstream report(out / "report.json");
    const Json json = Json::parse(report);
    size_t marked = 0;
    for (const Json& scene : json["scenes"]) marked += scene["status"] == "complete";
    EXPECT_EQ(marked, complete);
    EXPECT_EQ(json["scenes"].size(), 16u);
}

TEST(Resume, ATruncatedOrMissingOutputIsRenderedAgainAndAWholeOneIsNot) {
    const TempDir dir("candela_resume_truncated");
    const fs::path scenes = library(dir.path() / "scenes", 3);
    const std::string args = "render " + scenes.string() + " --out " + (dir.path() / "out/{name}.png").string() + kSize;
    ASSERT_EQ(run(args).exitCode, 0);
    const fs::path cut = dir.path() / "out/scene11.png";
    const std::string whole = readFile(cut);
    std::ofstream(cut, std::ios::binary | std::ios::trunc) << whole.substr(0, whole.size() / 2);  // an older writer's
    fs::remove(dir.path() / "out/scene12.png");
    std::ofstream(dir.path() / "out/scene12.png.tmp-0123456789abcdef") << "half";
    const auto untouched = fs::last_write_time(dir.path() / "out/scene10.png");
    ASSERT_FALSE(assets::imageFileComplete(cut));

    const Result resumed = run(args + " --resume");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.stderrText;
    EXPECT_NE(resumed.stdoutText.find("1 of 3 scenes were complete already"), std::string::npos) << resumed.stdoutText;
    EXPECT_EQ(readFile(cut), whole);
    EXPECT_TRUE(assets::imageFileComplete(dir.path() / "out/scene12.png"));
    EXPECT_FALSE(fs::exists(dir.path() / "out/scene12.png.tmp-0123456789abcdef"));
    EXPECT_EQ(fs::last_write_time(dir.path() / "out/scene10.png"), untouched);
}

// --outputs: the outputs besides colour beside a .png as NumPy arrays (a truncated one rendered
// again by --resume), or all of them as named channels of one .exr; a bad name is one line.
TEST(Resume, OutputsBesideTheImageAreFilesResumeChecksToo) {
    const TempDir dir("candela_resume_outputs");
    const fs::path scenes = library(dir.path() / "scenes", 2);
    const std::string args = "render " + scenes.string() + " --outputs color,depth,normal,ids --out " +
                             (dir.path() / "out/{name}.png").string() + kSize;
    ASSERT_EQ(run(args).exitCode, 0);
    const fs::path depth = dir.path() / "out/scene10.depth.npy";
    const std::string whole = readFile(depth);
    // A NumPy array of 120 × 160 float32 after its 64-byte-aligned header.
    ASSERT_EQ(whole.size(), 128u + 120 * 160 * 4);
    EXPECT_EQ(whole.substr(0, 6), "\x93NUMPY");
    EXPECT_NE(whole.find("'descr': '<f4', 'fortran_order': False, 'shape': (120, 160), }"), std::string::npos);
    EXPECT_NE(readFile(dir.path() / "out/scene11.normal.npy").find("'shape': (120, 160, 3)"), std::string::npos);
    EXPECT_NE(readFile(dir.path() / "out/scene11.instance_id.npy").find("'<u4'"), std::string::npos);
    std::ofstream(depth, std::ios::binary | std::ios::trunc) << whole.substr(0, whole.size() - 4);
    ASSERT_FALSE(assets::imageFileComplete(depth));
    const Result resumed = run(args + " --resume");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.stderrText;
    EXPECT_NE(resumed.stdoutText.find("1 of 2 scenes were complete already"), std::string::npos) << resumed.stdoutText;
    EXPECT_EQ(readFile(depth), whole);

    const fs::path exr = dir.path() / "one.exr";
    const Result one = run("render " + (scenes / "scene10.glb").string() + " --outputs color,depth,normal,ids --out " + exr.string() + kSize);
    ASSERT_EQ(one.exitCode, 0) << one.stderrText;
    const std::string bytes = readFile(exr);
    for (const char* channel : {"R", "A", "Z", "normal.X", "normal.Z", "node_id.id", "instance_id.id"})
        EXPECT_NE(bytes.find(std::string(channel) + '\0'), std::string::npos) << channel;
    EXPECT_TRUE(assets::imageFileComplete(exr));

    const Result bad = run("render --outputs color,albedo --out " + (dir.path() / "bad.png").string() + kSize);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.stderrText.find("--outputs: expected color, depth"), std::string::npos) << bad.stderrText;
    EXPECT_NE(bad.stderrText.find("got 'albedo'"), std::string::npos) << bad.stderrText;
}

}  // namespace
}  // namespace candela::test::resume_cli_test
