// The camera a render used, printed by --explain and --verbose as flags: rendering with those flags
// gives the same image, pixel for pixel. Runs the real executable on lavapipe under the validation
// layer.

#include "gltf_test_util.h"
#include "run_candela.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <set>

namespace candela::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSmall = " --width 96 --height 64 --validate --quiet";

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The flags of the "camera: ..." line in `text` ("" when there is none).
std::string cameraFlags(const std::string& text) {
    const size_t at = text.find("camera: --");
    if (at == std::string::npos) return "";
    const size_t start = at + std::string("camera: ").size();
    return text.substr(start, text.find('\n', start) - start);
}

// Renders `scene` with `args` and `kept`, then with the camera --explain printed and `kept`; both
// images must be the same.
void expectPrintedCameraReproduces(const fs::path& scene, const std::string& args, const std::string& kept = "") {
    TempDir dir("candela_camera_cli");
    const fs::path first = dir / "auto.png", second = dir / "printed.png";
    const Result framed = run("render --scene " + scene.string() + args + kept + " --explain --out " + first.string() + kSmall);
    ASSERT_EQ(framed.exitCode, 0) << framed.stderrText;
    const std::string flags = cameraFlags(framed.stdoutText);
    ASSERT_FALSE(flags.empty()) << framed.stdoutText;
    EXPECT_NE(flags.find("--camera-orbit"), std::string::npos) << flags;
    // --verbose prints the same line (on stderr, with the other information).
    const Result verbose = run("render --scene " + scene.string() + args + kept + " --verbose --out " + (dir / "v.png").string() +
                               " --width 96 --height 64 --validate");
    ASSERT_EQ(verbose.exitCode, 0) << verbose.stderrText;
    EXPECT_EQ(cameraFlags(verbose.stderrText), flags) << verbose.stderrText;
    const Result again = run("render --scene " + scene.string() + " " + flags + kept + " --out " + second.string() + kSmall);
    ASSERT_EQ(again.exitCode, 0) << again.stderrText;
    const std::string a = readFile(first), b = readFile(second);
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "rendering with '" << flags << "' drew another image than the framing it printed";
}

TEST(CameraCli, ThePrintedCameraReproducesTheDefaultFraming) {
    const fs::path models = assets::test::sharedModels();
    if (models.empty()) GTEST_SKIP() << "../shared/assets not present";
    expectPrintedCameraReproduces(models / "TwoSidedPlane/glTF/TwoSidedPlane.gltf", "");
}

TEST(CameraCli, ThePrintedCameraReproducesAChosenDirectionAndFieldOfView) {
    const fs::path models = assets::test::sharedModels();
    if (models.empty()) GTEST_SKIP() << "../shared/assets not present";
    expectPrintedCameraReproduces(models / "Duck/glTF-Binary/Duck.glb", " --camera-orbit -35,62,0 --fov 30");
}

TEST(CameraCli, ThePrintedCameraReproducesAnAnimatedStill) {
    const fs::path models = assets::test::sharedModels();
    if (models.empty()) GTEST_SKIP() << "../shared/assets not present";
    expectPrintedCameraReproduces(models / "BoxAnimated/glTF-Binary/BoxAnimated.glb", "", " --time 1.5");
}

// --explain says what framing fitted: the vertices of the pose shown for a still, of every frame's
// pose for a sequence (which keeps one camera), of the scene as loaded when nothing moves.
TEST(CameraCli, ExplainSaysWhatFramingFitted) {
    const fs::path models = assets::test::sharedModels();
    if (models.empty()) GTEST_SKIP() << "../shared/assets not present";
    TempDir dir("candela_camera_cli_framing");
    const std::string box = (models / "BoxAnimated/glTF-Binary/BoxAnimated.glb").string();
    const Result still = run("render --scene " + box + " --time 1.5 --explain --out " + (dir / "s.png").string() + kSmall);
    ASSERT_EQ(still.exitCode, 0) << still.stderrText;
    EXPECT_NE(still.stdoutText.find("framing: the vertices of the pose at 1.5 s: the target at the centre of their box, the distance "
                                    "R / sin 15°"),
              std::string::npos)
        << still.stdoutText;
    const Result sequence = run("render --scene " + box + " --frames 3 --fps 2 --explain --out " + (dir / "q_%d.png").string() + kSmall);
    ASSERT_EQ(sequence.exitCode, 0) << sequence.stderrText;
    EXPECT_NE(sequence.stdoutText.find("framing: the vertices of the poses at 3 times (0 s to 1 s)"), std::string::npos)
        << sequence.stdoutText;
    std::set<std::string> cameras;
    for (size_t at = 0; (at = sequence.stdoutText.find("camera: --", at)) != std::string::npos; ++at)
        cameras.insert(sequence.stdoutText.substr(at, sequence.stdoutText.find('\n', at) - at));
    EXPECT_EQ(cameras.size(), 1u) << sequence.stdoutText;  // the camera holds still
    const Result rest = run("render --scene " + box + " --animation none --explain --out " + (dir / "r.png").string() + kSmall);
    ASSERT_EQ(rest.exitCode, 0) << rest.stderrText;
    EXPECT_NE(rest.stdoutText.find("framing: the scene's vertices:"), std::string::npos) << rest.stdoutText;
}

TEST(CameraCli, ATurntableKeepsOneDistance) {
    const fs::path models = assets::test::sharedModels();
    if (models.empty()) GTEST_SKIP() << "../shared/assets not present";
    TempDir dir("candela_camera_cli_turntable");
    const Result r = run("render --scene " + (models / "Duck/glTF-Binary/Duck.glb").string() +
                         " --frames 4 --turntable 360 --verbose --out " + (dir / "t_%02d.png").string() +
                         " --width 96 --height 64 --validate --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    // "--camera-orbit θ,75,r": θ 0, 90, 180, 270 and one r, the largest the four directions need.
    std::vector<std::string> orbits;
    for (size_t at = 0; (at = r.stderrText.find("--camera-orbit ", at)) != std::string::npos; ++at)
        orbits.push_back(r.stderrText.substr(at + 15, r.stderrText.find(' ', at + 15) - at - 15));
    ASSERT_EQ(orbits.size(), 4u) << r.stderrText;
    const std::string radius = orbits[0].substr(orbits[0].rfind(',') + 1);
    for (size_t i = 0; i < orbits.size(); ++i)
        EXPECT_EQ(orbits[i], std::to_string(90 * i) + ",75," + radius) << r.stderrText;
}

// --views N: N images from the sphere's directions at one distance, and transforms.json beside them
// with each image's camera (docs/datasets.md); two scenes' views may not share one transforms.json.
TEST(CameraCli, ViewsWriteTheirImagesAndTransformsJson) {
    TempDir dir("candela_camera_cli_views");
    const Result r = run("render --views 5 --view-ring 10 --light-seed 3 --out " + (dir / "grid/v_%02d.png").string() + kSmall);
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    std::ifstream in(dir / "grid/transforms.json");
    const nlohmann::json json = nlohmann::json::parse(in);
    ASSERT_EQ(json["frames"].size(), 5u);
    EXPECT_EQ(json["w"], 96);
    EXPECT_EQ(json["h"], 64);
    std::set<double> rotations;
    for (size_t i = 0; i < 5; ++i) {
        const nlohmann::json& frame = json["frames"][i];
        char name[16];
        std::snprintf(name, sizeof name, "v_%02zu.png", i);
        EXPECT_EQ(frame["file_path"], name);
        EXPECT_TRUE(fs::exists(dir / "grid" / name));
        // The ring 10° above the horizon, azimuths 72° apart: the eye at height r·sin 10°.
        const auto& m = frame["transform_matrix"];
        const double x = m[0][3], y = m[1][3], z = m[2][3];
        const double radius = std::sqrt(x * x + y * y + z * z);
        EXPECT_NEAR(y / radius, std::sin(10.0 * 3.14159265358979 / 180.0), 1e-5) << i;
        EXPECT_NEAR(std::atan2(x, z) * 180.0 / 3.14159265358979, i <= 2 ? 72.0 * i : 72.0 * i - 360.0, 1e-3) << i;
        rotations.insert(frame["environment_rotation_degrees"].get<double>());
    }
    EXPECT_EQ(rotations.size(), 5u);  // jittered lighting
    // Two scenes' views in one folder: a cameras file each, named after the scene.
    for (const char* name : {"a", "b"}) {
        assets::test::GltfBuilder b;
        b.addTriangle();
        b.writeGlb(dir.path(), name);
    }
    const Result both = run("render --views 2 " + (dir / "a.glb").string() + " " + (dir / "b.glb").string() + " --out " +
                            (dir / "out/{name}_%02d.png").string() + kSmall);
    ASSERT_EQ(both.exitCode, 0) << both.stderrText;
    EXPECT_FALSE(fs::exists(dir / "out/transforms.json"));
    for (const char* name : {"a", "b"}) {
        std::ifstream file(dir / "out" / (std::string(name) + ".transforms.json"));
        const nlohmann::json cameras = nlohmann::json::parse(file);
        EXPECT_EQ(cameras["frames"][1]["file_path"], std::string(name) + "_01.png");
    }
}

TEST(CameraCli, AGltfCameraIsPrintedByItsIndex) {
    const fs::path models = assets::test::sharedModels();
    if (models.empty()) GTEST_SKIP() << "../shared/assets not present";
    TempDir dir("candela_camera_cli_gltf");
    const Result r = run("render --scene " + (models / "Cameras/glTF/Cameras.gltf").string() + " --camera 1 --explain --out " +
                         (dir / "c.png").string() + kSmall);
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_EQ(cameraFlags(r.stdoutText), "--camera 1") << r.stdoutText;
}

}  // namespace
}  // namespace candela::test
