// `candela render` over many scenes in one run: the same images as one run per scene, one
// environment precompute, failures reported without stopping the run, shards that cover a library
// once, output patterns, and the JSON report. Runs the real executable on lavapipe under the
// validation layer.

#include "gltf_test_util.h"
#include "run_candela.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <set>

namespace candela::test::render_batch_test {
namespace {

namespace fs = std::filesystem;
using assets::test::GltfBuilder;
using assets::test::writeFile;
using Json = nlohmann::json;

constexpr const char* kSmall = " --width 48 --height 32 --validate --quiet";

Json readJson(const fs::path& file) {
    std::ifstream in(file);
    return Json::parse(in);
}

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A triangle with a material of base colour `rgb`, written as NAME.glb in `dir`.
fs::path triangle(const fs::path& dir, const std::string& name, std::array<float, 3> rgb = {0.8f, 0.3f, 0.2f}) {
    GltfBuilder b;
    b.addTriangle();
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    b.doc["materials"] = Json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {rgb[0], rgb[1], rgb[2], 1.0}}}}}});
    fs::create_directories(dir);
    return b.writeGlb(dir, name);
}

// The triangle with KHR_materials_variants "red" and "blue".
fs::path variantsTriangle(const fs::path& dir) {
    GltfBuilder b;
    b.addTriangle();
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    b.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"] =
        Json::array({{{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {1}}}});
    b.doc["materials"] = Json::array({Json::object(),
                                      {{"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 0.0, 0.0, 1.0}}}}},
                                      {{"pbrMetallicRoughness", {{"baseColorFactor", {0.0, 0.0, 1.0, 1.0}}}}}});
    b.doc["extensionsUsed"] = {"KHR_materials_variants"};
    b.doc["extensions"]["KHR_materials_variants"]["variants"] = Json::array({{{"name", "red"}}, {{"name", "blue"}}});
    fs::create_directories(dir);
    return b.writeGlb(dir, "shoe");
}

TEST(RenderBatch, OneRunRendersWhatOneRunPerSceneRendersWithOnePrecompute) {
    const fs::path models = assets::test::sharedModels();
    if (models.empty()) GTEST_SKIP() << "shared assets missing";
    TempDir dir("candela_batch");
    // A textured scene, a scene with a sheen (the sheen cube), and one without textures, in an order
    // where the sheen comes second: the first precompute must already serve it.
    const std::vector<fs::path> scenes = {models / "BoxTextured/glTF-Binary/BoxTextured.glb",
                                          models / "SheenCloth/glTF/SheenCloth.gltf", triangle(dir.path(), "triangle")};
    std::string args = "render --out " + (dir / "batch/{name}.png").string() + " --report " + (dir / "report.json").string();
    for (const fs::path& scene : scenes) args += " " + scene.string();
    const Result batch = run(args + kSmall);
    ASSERT_EQ(batch.exitCode, 0) << batch.stderrText;
    EXPECT_EQ(batch.stderrText, "");  // valid files render quietly
    for (const fs::path& scene : scenes) {
        const std::string name = scene.stem().string();
        const fs::path alone = dir / ("alone_" + name + ".png");
        const Result one = run("render --scene " + scene.string() + " --out " + alone.string() + kSmall);
        ASSERT_EQ(one.exitCode, 0) << one.stderrText;
        EXPECT_EQ(readFile(dir / "batch" / (name + ".png")), readFile(alone)) << name << ": the batch drew another image";
    }
    const Json report = readJson(dir / "report.json");
    EXPECT_EQ(report["precomputes"], 1);
    EXPECT_EQ(report["scenesListed"], 3);
    EXPECT_EQ(report["scenesFailed"], 0);
    EXPECT_GT(report["precomputeMs"].get<double>(), 0.0);
    ASSERT_EQ(report["scenes"].size(), 3u);
    const Json& box = report["scenes"][0];
    EXPECT_EQ(box["status"], "ok");
    EXPECT_EQ(box["name"], "BoxTextured");
    EXPECT_EQ(box["triangles"], 12);
    EXPECT_EQ(box["draws"], 1);
    ASSERT_EQ(box["textures"].size(), 1u);
    EXPECT_EQ(box["textures"][0]["format"], "PNG");
    EXPECT_EQ(box["textures"][0]["width"], 256);
    EXPECT_GT(box["textures"][0]["encodedBytes"].get<uint64_t>(), 0u);
    EXPECT_GE(box["textures"][0]["deviceBytes"].get<uint64_t>(), 256u * 256u * 4u);  // RGBA8 with mips
    EXPECT_EQ(box["outputs"], Json::array({(dir / "batch/BoxTextured.png").string()}));
    EXPECT_GT(box["loadMs"].get<double>(), 0.0);
    EXPECT_GT(box["uploadMs"].get<double>(), 0.0);
    ASSERT_EQ(box["frameMs"].size(), 1u);
    const Json& cloth = report["scenes"][1];
    const std::vector<std::string> extensions = cloth["extensions"];
    EXPECT_NE(std::find(extensions.begin(), extensions.end(), "KHR_materials_sheen"), extensions.end());
    for (const Json& s : report["scenes"]) {
        EXPECT_EQ(s["validationMessages"], 0);
        EXPECT_GT(s["hostBytes"].get<uint64_t>(), 0u);
    }
}

TEST(RenderBatch, AFailingSceneIsReportedAndTheRunGoesOn) {
    TempDir dir("candela_batch");
    triangle(dir / "lib", "a");
    writeFile(dir / "lib/b.glb", std::string("glTF not really"));
    triangle(dir / "lib", "c");
    const Result r = run("render " + (dir / "lib").string() + " --out " + (dir / "out/{name}.png").string() + " --report " +
                         (dir / "report.json").string() + kSmall);
    EXPECT_EQ(r.exitCode, 2) << r.stderrText;
    EXPECT_TRUE(fs::exists(dir / "out/a.png"));
    EXPECT_TRUE(fs::exists(dir / "out/c.png"));  // after the failure
    EXPECT_FALSE(fs::exists(dir / "out/b.png"));
    const std::string b = (dir / "lib/b.glb").string();
    EXPECT_NE(r.stderrText.find("1 of 3 scenes failed:\n  " + b + ": "), std::string::npos) << r.stderrText;
    const Json report = readJson(dir / "report.json");
    EXPECT_EQ(report["scenesFailed"], 1);
    EXPECT_EQ(report["scenes"][1]["status"], "failed");
    EXPECT_EQ(report["scenes"][1]["exitCode"], 2);
    EXPECT_EQ(report["scenes"][1]["error"].get<std::string>().rfind(b + ": ", 0), 0u);
    EXPECT_EQ(report["scenes"][2]["status"], "ok");
}

// Images are written while the next scene is drawn (app/image_writer.h): one that cannot be written
// fails its own scene, not the one drawn when the failure is known, and the run goes on.
TEST(RenderBatch, AnImageThatCannotBeWrittenFailsItsSceneAlone) {
    TempDir dir("candela_batch");
    for (const char* name : {"a", "b", "c"}) triangle(dir / "lib", name);
    fs::create_directories(dir / "out/b.png");  // a folder where b's image goes
    const Result r = run("render " + (dir / "lib").string() + " --out " + (dir / "out/{name}.png").string() + " --report " +
                         (dir / "report.json").string() + kSmall);
    EXPECT_NE(r.exitCode, 0) << r.stderrText;
    EXPECT_TRUE(fs::is_regular_file(dir / "out/a.png"));
    EXPECT_TRUE(fs::is_regular_file(dir / "out/c.png"));
    const std::string b = (dir / "lib/b.glb").string(), bOut = (dir / "out/b.png").string();
    EXPECT_NE(r.stderrText.find("1 of 3 scenes failed:\n  " + b + ": "), std::string::npos) << r.stderrText;
    EXPECT_NE(r.stderrText.find(bOut), std::string::npos) << r.stderrText;
    const Json report = readJson(dir / "report.json");
    EXPECT_EQ(report["scenesFailed"], 1);
    EXPECT_EQ(report["scenes"][0]["status"], "ok");
    EXPECT_EQ(report["scenes"][1]["status"], "failed");
    EXPECT_NE(report["scenes"][1]["error"].get<std::string>().find(bOut), std::string::npos) << report["scenes"][1]["error"];
    EXPECT_EQ(report["scenes"][2]["status"], "ok");
    // The images written are said so, in order; the one that was not is not.
    const size_t a = r.stdoutText.find("wrote " + (dir / "out/a.png").string()), c = r.stdoutText.find("wrote " + (dir / "out/c.png").string());
    EXPECT_NE(a, std::string::npos) << r.stdoutText;
    EXPECT_NE(c, std::string::npos) << r.stdoutText;
    EXPECT_LT(a, c);
    EXPECT_EQ(r.stdoutText.find("wrote " + bOut), std::string::npos) << r.stdoutText;
}

// In a sequence, a frame that cannot be written stops the run with the error naming the file.
TEST(RenderBatch, AFrameThatCannotBeWrittenStopsItsSequence) {
    TempDir dir("candela_batch");
    const fs::path scene = triangle(dir / "lib", "a");
    fs::create_directories(dir / "out/f_0001.png");
    const Result r = run("render --scene " + scene.string() + " --frames 4 --out " + (dir / "out/f_%04d.png").string() + kSmall);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.stderrText.find((dir / "out/f_0001.png").string()), std::string::npos) << r.stderrText;
    EXPECT_TRUE(fs::is_regular_file(dir / "out/f_0000.png"));
    EXPECT_FALSE(fs::exists(dir / "out/f_0003.png")) << "the sequence stopped at the failed frame (one frame after it at most)";
}

TEST(RenderBatch, ShardsCoverEverySceneExactlyOnce) {
    TempDir dir("candela_batch");
    for (int i = 0; i < 7; ++i) triangle(dir / "lib" / ("group" + std::to_string(i % 3)), "t" + std::to_string(i));
    std::multiset<std::string> rendered;
    for (int shard = 1; shard <= 3; ++shard) {
        const fs::path report = dir / ("shard" + std::to_string(shard) + ".json");
        const Result r = run("render " + (dir / "lib").string() + " --shard " + std::to_string(shard) + "/3 --out " +
                             (dir / "out/{path}.png").string() + " --report " + report.string() + kSmall);
        ASSERT_EQ(r.exitCode, 0) << r.stderrText;
        const Json json = readJson(report);
        EXPECT_EQ(json["scenesListed"], 7);
        EXPECT_EQ(json["shard"]["index"], shard);
        for (const Json& s : json["scenes"]) rendered.insert(s["path"].get<std::string>());
    }
    EXPECT_EQ(rendered.size(), 7u);
    for (int i = 0; i < 7; ++i) {
        const std::string path = "group" + std::to_string(i % 3) + "/t" + std::to_string(i);
        EXPECT_EQ(rendered.count(path), 1u) << path;
        EXPECT_TRUE(fs::exists(dir / "out" / (path + ".png"))) << path;
    }
}

TEST(RenderBatch, AShardWithoutScenesRendersNothingAndSucceeds) {
    TempDir dir("candela_batch");
    const fs::path scene = triangle(dir.path(), "only");
    const Result r = run("render " + scene.string() + " --shard 2/2 --out " + (dir / "{name}.png").string() + " --report " +
                         (dir / "report.json").string() + kSmall);
    EXPECT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_FALSE(fs::exists(dir / "only.png"));
    const Json report = readJson(dir / "report.json");
    EXPECT_EQ(report["scenesListed"], 1);
    EXPECT_EQ(report["scenes"].size(), 0u);
}

TEST(RenderBatch, VariantsAndSequencesArePerScene) {
    TempDir dir("candela_batch");
    const fs::path shoe = variantsTriangle(dir / "lib");
    triangle(dir / "lib", "plain");
    const Result r = run("render " + (dir / "lib").string() + " --variant all --frames 2 --turntable 90 --out " +
                         (dir / "out/{name}-{variant}-{frame}.png").string() + kSmall);
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    for (const char* file : {"shoe-red-0000", "shoe-red-0001", "shoe-blue-0000", "shoe-blue-0001", "plain-default-0000",
                             "plain-default-0001"})
        EXPECT_TRUE(fs::exists(dir / "out" / (std::string(file) + ".png"))) << file;
    EXPECT_NE(readFile(dir / "out/shoe-red-0000.png"), readFile(dir / "out/shoe-blue-0000.png"));
    EXPECT_NE(readFile(dir / "out/plain-default-0000.png"), readFile(dir / "out/plain-default-0001.png"));  // turned
}

TEST(RenderBatch, NothingOfASceneStaysOnTheDeviceAfterIt) {
    TempDir dir("candela_batch");
    // Six scenes alike, each with a 128 x 128 texture (64 KiB + mips on the device).
    assets::test::Bytes pixels;
    for (int i = 0; i < 128 * 128; ++i) pixels.insert(pixels.end(), {uint8_t(i), uint8_t(i >> 7), 200, 255});
    const assets::test::Bytes png = assets::test::makePng(128, 128, 8, 6, pixels);
    for (int i = 0; i < 6; ++i) assets::test::texturedTriangle("", png).writeGlb(dir / "lib", "t" + std::to_string(i));
    const Result r = run("render " + (dir / "lib").string() + " --out " + (dir / "out/{name}.png").string() + " --report " +
                         (dir / "report.json").string() + kSmall);
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    const Json report = readJson(dir / "report.json");
    ASSERT_EQ(report["scenes"].size(), 6u);
    // The first scene's frame also ran the environment's precompute (its inputs are freed after
    // it); from the second on, what a scene uses while it renders and what stays after it are the
    // same for each, the texture's bytes apart.
    const Json& second = report["scenes"][1];
    EXPECT_GE(second["textureDeviceBytes"].get<uint64_t>(), 128u * 128u * 4u);
    for (size_t i = 1; i < 6; ++i) {
        const Json& s = report["scenes"][i];
        EXPECT_EQ(s["deviceBytes"], second["deviceBytes"]) << s["name"];
        EXPECT_EQ(s["retainedDeviceBytes"], second["retainedDeviceBytes"]) << s["name"];
    }
    EXPECT_LE(second["retainedDeviceBytes"].get<uint64_t>() + second["textureDeviceBytes"].get<uint64_t>(),
              second["deviceBytes"].get<uint64_t>());
}

TEST(RenderBatch, OutputsThatWouldCollideAreRefusedBeforeRendering) {
    TempDir dir("candela_batch");
    triangle(dir / "lib/a", "Box");
    triangle(dir / "lib/b", "Box");
    Result r = run("render " + (dir / "lib").string() + " --out " + (dir / "{name}.png").string() + kSmall);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.stderrText.find("would both write " + (dir / "Box.png").string() + " (use {path}"), std::string::npos) << r.stderrText;
    r = run("render " + (dir / "lib").string() + " --out " + (dir / "x.png").string() + kSmall);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.stderrText.find("give a pattern with {name} or {path}"), std::string::npos) << r.stderrText;
    r = run("render " + (dir / "lib").string() + " --variant all --out " + (dir / "{path}.png").string() + kSmall);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.stderrText.find("--variant all: --out needs {variant}"), std::string::npos) << r.stderrText;
    r = run("render " + (dir / "lib").string() + " --out " + (dir / "{scene}.png").string() + kSmall);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.stderrText.find("unknown field {scene}"), std::string::npos) << r.stderrText;
    EXPECT_FALSE(fs::exists(dir / "Box.png"));
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

}  // namespace
}  // namespace candela::test::render_batch_test
