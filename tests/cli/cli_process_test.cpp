// The `candela` executable end to end: exit codes, one-line errors, and the files it writes.
#include "run_candela.h"
#include "test_paths.h"
#include "temp_dir.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <stb_image.h>
#include <OpenEXR/ImfRgbaFile.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

using candela::test::Result;
using candela::test::run;

// The process's scratch folder, removed when the process exits (ctest runs each test in its own;
// the sanitized stage runs them all in one). Made again when a test removed it.
std::filesystem::path tempDir() {
    static const candela::test::TempDir dir("candela_cli");
    std::filesystem::create_directories(dir.path());
    return dir.path();
}

// A bad-input row: the arguments, and a fragment the one-line error must contain.
struct BadInput {
    const char* name;
    const char* args;
    const char* fragment;
};

void writeFile(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

void appendU32(std::string& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out += char(v >> (8 * i));
}

// The scene files the bad-input rows name as {dir}/NAME, written into a fresh temporary folder:
//   triangle.gltf (+ triangle.bin)  a valid one-triangle scene without cameras
//   truncated.glb                   the same triangle as GLB, cut to half its length
//   syntax.gltf                     a JSON syntax error (trailing comma)
//   scene.obj                       a Wavefront OBJ triangle (not glTF)
//   folder.gltf/                    a directory
//   variants.gltf                   the triangle with KHR_materials_variants "red" and "blue"
std::filesystem::path writeSceneFiles() {
    const auto dir = tempDir() / "scenes";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "folder.gltf");
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
    const std::string json =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
        R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36%s}]})";
    auto withUri = [&](const std::string& uri) {
        std::string out = json;
        return out.replace(out.find("%s"), 2, uri);
    };
    writeFile(dir / "triangle.bin", bin);
    writeFile(dir / "truncated.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n\x01\x02");
    writeFile(dir / "triangle.gltf", withUri(R"(,"uri":"triangle.bin")"));
    std::string variants = withUri(R"(,"uri":"triangle.bin")");
    variants.replace(variants.find(R"({"attributes":{"POSITION":0}})"), std::string(R"({"attributes":{"POSITION":0}})").size(),
                     R"({"attributes":{"POSITION":0},"material":0,"extensions":{"KHR_materials_variants":)"
                     R"({"mappings":[{"material":1,"variants":[1]}]}}})");
    variants.insert(variants.size() - 1, R"(,"materials":[{},{}],"extensions":{"KHR_materials_variants":)"
                                         R"({"variants":[{"name":"red"},{"name":"blue"}]}})");
    writeFile(dir / "variants.gltf", variants);
    std::string chunk = withUri("");
    while (chunk.size() % 4) chunk += ' ';
    std::string glb;
    appendU32(glb, 0x46546C67);  // "glTF"
    appendU32(glb, 2);
    appendU32(glb, uint32_t(12 + 8 + chunk.size() + 8 + bin.size()));
    appendU32(glb, uint32_t(chunk.size()));
    appendU32(glb, 0x4E4F534A);  // "JSON"
    glb += chunk;
    appendU32(glb, uint32_t(bin.size()));
    appendU32(glb, 0x004E4942);  // "BIN"
    glb += bin;
    writeFile(dir / "truncated.glb", glb.substr(0, glb.size() / 2));
    writeFile(dir / "syntax.gltf", R"({"asset": {"version": "2.0"},})");
    writeFile(dir / "scene.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    writeFile(dir / "image.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16));
    writeFile(dir / "nested.txt", "triangle.gltf\n@other.txt\n");
    writeFile(dir / "comments.txt", "# nothing but comments\n\n   \n");
    writeFile(dir / "binary.txt", std::string("\x7f" "ELF\0\x02\x01", 8));
    writeFile(dir / "missing.txt", (dir / "nope.glb").string() + "\n");
    return dir;
}

// Replaces every "{dir}" in `text` with `dir`.
std::string expand(std::string text, const std::string& dir) {
    for (size_t at = text.find("{dir}"); at != std::string::npos; at = text.find("{dir}", at + dir.size()))
        text.replace(at, 5, dir);
    return text;
}

class BadInputTest : public ::testing::TestWithParam<BadInput> {
protected:
    static void SetUpTestSuite() { sDir = writeSceneFiles(); }
    static void TearDownTestSuite() { std::filesystem::remove_all(sDir); }
    static inline std::filesystem::path sDir;
};

TEST_P(BadInputTest, OneLineErrorAndNonZeroExit) {
    const BadInput& row = GetParam();
    const std::string args = expand(row.args, sDir.string()), fragment = expand(row.fragment, sDir.string());
    const Result r = run(args);
    EXPECT_NE(r.exitCode, 0) << args;
    EXPECT_NE(r.exitCode, -1) << "crashed: " << args;
    ASSERT_FALSE(r.stderrText.empty());
    EXPECT_EQ(r.stderrText.find('\n'), r.stderrText.size() - 1) << "expected one line, got:\n" << r.stderrText;
    EXPECT_NE(r.stderrText.find("candela: error: "), std::string::npos) << r.stderrText;
    EXPECT_NE(r.stderrText.find(fragment), std::string::npos) << r.stderrText;
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, BadInputTest,
    ::testing::Values(BadInput{"UnknownFlag", "render --frobnicate", "unknown flag --frobnicate for render"},
                      BadInput{"UnknownFlagNamesTheNearest", "render --scen x.glb", "unknown flag --scen for render (did you mean --scene?)"},
                      BadInput{"BenchTakesNoGraphExport", "bench --graph-json {dir}/g.json --out {dir}/x.png --explain",
                               "bench does not take --graph-json (it is a flag of render)"},
                      BadInput{"ViewTakesNoGraphExport", "view --graph-dot {dir}/g.dot --explain",
                               "view does not take --graph-dot (it is a flag of render)"},
                      BadInput{"UnknownCommand", "explode", "unknown command 'explode'"},
                      BadInput{"SceneListMissing", "render @{dir}/nolist.txt --out {dir}/x.png", "@{dir}/nolist.txt: cannot open the list of scenes"},
                      BadInput{"SceneListNested", "render @{dir}/nested.txt --out {dir}/x.png",
                               "@{dir}/nested.txt line 2: a list of scenes cannot name another list (@other.txt)"},
                      BadInput{"SceneListOnlyComments", "render @{dir}/comments.txt --out {dir}/x.png", "no glTF scene (.gltf or .glb) in @{dir}/comments.txt"},
                      BadInput{"SceneListBinary", "render @{dir}/binary.txt --out {dir}/x.png", "@{dir}/binary.txt line 1: a NUL byte"},
                      BadInput{"SceneListNamesAMissingFile", "render @{dir}/missing.txt --out {dir}/x.png", "{dir}/nope.glb: cannot open"},
                      BadInput{"FolderWithoutScenes", "render {dir}/folder.gltf --out {dir}/x.png", "no glTF scene (.gltf or .glb) in {dir}/folder.gltf"},
                      BadInput{"ShardBeyondCount", "render --shard 5/4", "--shard: expected I/N with 1 <= I <= N (this machine's share of N), or auto, got '5/4'"},
                      BadInput{"OutPatternUnknownField", "render --out {dir}/{scene}.png", "unknown field {scene}"},
                      BadInput{"PngAsScene", "render --scene {dir}/image.png --out {dir}/x.png", "{dir}/image.png: not a glTF file: looks like a PNG image"},
                      BadInput{"OutIsAFolder", "render --out {dir}/renders/", "--out {dir}/renders/: names a folder; give a file in it, e.g. --out {dir}/renders/candela.png"},
                      BadInput{"FrameFieldWithoutFrames", "render --out {dir}/x_%04d.png", "--out {dir}/x_%04d.png: a frame number field without --frames N"},
                      BadInput{"ViewsWithFrames", "render --views 3 --frames 2 --out {dir}/v_%02d.png", "--views: views are of one pose; not with --frames or --turntable"},
                      BadInput{"ViewRingWithoutViews", "render --view-ring 20 --out {dir}/x.png", "--view-ring: puts --views on a ring; give --views N"},
                      BadInput{"LightSeedOfAStill", "render --light-seed 4 --out {dir}/x.png", "--light-seed: jitters the lighting of --views or --frames; give one"},
                      BadInput{"LightSeedNotANumber", "render --views 2 --light-seed -3 --out {dir}/v_%02d.png", "--light-seed: expected a whole number, got '-3'"},
                      BadInput{"ViewsOfAGltfCamera", "render --views 2 --camera 0 --out {dir}/v_%02d.png", "views of a scene need the orbit camera"},
                      BadInput{"FrameBracesWithoutFrames", "render --out '{dir}/x_{frame}.png'", "a frame number field without --frames N"},
                      BadInput{"ZeroWidth", "render --width 0 --out /tmp/candela_zero.png", "--width: must be at least 1"},
                      BadInput{"ZeroHeight", "render --height 0 --out /tmp/candela_zero.png", "--height: must be at least 1"},
                      BadInput{"NegativeWidth", "render --width -5", "--width: expected a whole number"},
                      BadInput{"TrailingGarbageHeight", "render --height 12abc", "--height: expected a whole number"},
                      BadInput{"WidthBeyondUint32", "render --width 99999999999", "--width: expected a whole number"},
                      BadInput{"WidthBeyondDeviceLimit", "render --width 1000000 --out /tmp/candela_big.png", "exceeds the device limit"},
                      BadInput{"UnwritableOutput", "render --out /dev/null/x.png", "/dev/null/x.png: cannot write"},
                      BadInput{"UnknownExtension", "render --out /tmp/candela.bmp", "unknown output format '.bmp'"},
                      BadInput{"NoExtension", "render --out /tmp/candela_noext", "unknown output format '(none)'"},
                      BadInput{"OutputIsDirectory", "render --out /tmp", "/tmp: "},
                      BadInput{"MissingValue", "render --width", "--width needs a value"},
                      BadInput{"DeviceNameMatchesNothing", "render --device no-such-gpu --out /tmp/candela_dev.png", "matches no Vulkan device"},
                      BadInput{"DeviceIndexOutOfRange", "render --device 42 --out /tmp/candela_dev.png", "no such device index"},
                      BadInput{"InfoDeviceMatchesNothing", "info --device no-such-gpu", "matches no Vulkan device"},
                      BadInput{"SwitchWithValue", "render --validate=yes", "--validate takes no value"},
                      BadInput{"UnknownPassToDisable", "render --disable-pass nosuchpass --out /tmp/candela_np.png", "nosuchpass"},
                      BadInput{"PassThatCannotBeDisabled",
                               "render --width 16 --height 16 --disable-pass ibl_prefilter --out /tmp/candela_np.png",
                               "cannot disable pass 'ibl_prefilter': it writes the specular map's rough levels"},
                      // Scenes ({dir}: the files of writeSceneFiles) and the scene, camera and image options.
                      BadInput{"VariantUnknown", "render --scene {dir}/variants.gltf --variant green --out {dir}/x.png",
                               "--variant: {dir}/variants.gltf has no variant 'green' (its variants: red, blue)"},
                      BadInput{"VariantWithoutVariants", "render --scene {dir}/triangle.gltf --variant red --out {dir}/x.png",
                               "--variant red: {dir}/triangle.gltf has no material variants (KHR_materials_variants)"},
                      BadInput{"SceneMissing", "render --scene {dir}/missing.gltf --out {dir}/x.png", "{dir}/missing.gltf: cannot open: No such file"},
                      BadInput{"SceneIsDirectory", "render --scene {dir}/folder.gltf --out {dir}/x.png", "{dir}/folder.gltf: is a directory"},
                      BadInput{"SceneTruncatedGlb", "render --scene {dir}/truncated.glb --out {dir}/x.png", "{dir}/truncated.glb: truncated GLB: header says"},
                      BadInput{"SceneJsonSyntaxError", "render --scene {dir}/syntax.gltf --out {dir}/x.png", "{dir}/syntax.gltf: invalid glTF: [json.exception.parse_error.101] parse error at line 1, column 30"},
                      // The loader tells .gltf from .glb by content and ignores the extension (a glTF file
                      // named .obj loads): an OBJ file fails as JSON that does not parse.
                      // The device starts while a single scene loads: a bad file is still what is
                      // reported, not a device that could not start.
                      BadInput{"SceneErrorBeforeDeviceError", "render --device no-such-gpu --scene {dir}/syntax.gltf --out {dir}/x.png",
                               "{dir}/syntax.gltf: invalid glTF: [json.exception.parse_error.101]"},
                      BadInput{"SceneNotGltf", "render --scene {dir}/scene.obj --out {dir}/x.png", "{dir}/scene.obj: invalid glTF: [json.exception.parse_error.101] parse error at line 1, column 1"},
                      BadInput{"CameraBeyondSceneCameras", "render --scene {dir}/triangle.gltf --camera 3 --out {dir}/x.png", "--camera 3: the scene has 0 cameras"},
                      BadInput{"CameraOrbitTwoNumbers", "render --camera-orbit 30,45 --out {dir}/x.png", "--camera-orbit: expected three comma-separated numbers, got '30,45'"},
                      BadInput{"FovZero", "render --fov 0 --out {dir}/x.png", "--fov: expected degrees between 0 and 180, got '0'"},
                      BadInput{"TonemapUnknown", "render --tonemap filmic --out {dir}/x.png", "--tonemap: expected pbr-neutral, aces, agx, reinhard or linear, got 'filmic'"},
                      BadInput{"ShadingUnknown", "render --shading lambert --out {dir}/x.png", "--shading: expected pbr, pbr-schlick-ggx or blinn-phong, got 'lambert'"},
                      BadInput{"BackgroundFiveHexDigits", "render --background '#12345' --out {dir}/x.png", "--background: expected #rrggbb, got '#12345'"},
                      BadInput{"BackgroundSkyboxWithoutEnvironment", "render --env none --background skybox --out {dir}/x.png", "--background skybox: there is no environment to show (--env none)"},
                      // Environments and image-based lighting.
                      BadInput{"EnvironmentMissing", "render --env {dir}/missing.hdr --out {dir}/x.png", "{dir}/missing.hdr: "},
                      // The device starts while the environment loads: a bad environment is still
                      // what is reported, as when the device started after it.
                      BadInput{"EnvironmentErrorBeforeDeviceError", "render --device no-such-gpu --env {dir}/missing.hdr --out {dir}/x.png",
                               "{dir}/missing.hdr: cannot open"},
                      BadInput{"EnvironmentTruncated", "render --env {dir}/truncated.hdr --out {dir}/x.png", "{dir}/truncated.hdr: "},
                      BadInput{"EnvironmentIntensityNegative", "render --env-intensity -1 --out {dir}/x.png", "--env-intensity: must be ≥ 0, got '-1'"},
                      BadInput{"EnvironmentRotationNotANumber", "render --env-rotation east --out {dir}/x.png", "--env-rotation: expected a number, got 'east'"},
                      BadInput{"IrradianceUnknown", "render --irradiance sh16 --out {dir}/x.png", "--irradiance: expected sh9 or cube, got 'sh16'"},
                      BadInput{"IblCubeSizeNotPowerOfTwo", "render --ibl-cube-size 100 --out {dir}/x.png", "--ibl-cube-size 100: must be a power of two from 16 to 2048"},
                      BadInput{"IblShSizeAboveCube", "render --ibl-cube-size 64 --ibl-sh-size 128 --out {dir}/x.png", "--ibl-sh-size 128: must be a power of two from 1 to 64"},
                      BadInput{"IblPrefilterSamplesZero", "render --ibl-prefilter-samples 0 --out {dir}/x.png", "--ibl-prefilter-samples 0: must be from 1 to 65536"},
                      BadInput{"IblBrightTexelsTooMany", "render --ibl-bright-texels 70000 --out {dir}/x.png", "--ibl-bright-texels 70000: must be from 0 to 65536"},
                      BadInput{"IblReportWithoutEnvironment", "ibl-report --env none --out {dir}/r", "--env: ibl-report needs an environment"},
                      BadInput{"IblReportZeroRepeats", "ibl-report --repeats 0 --out {dir}/r", "--repeats: must be at least 1"},
                      BadInput{"IblReportUnwritableOut", "ibl-report --out /proc/candela-report", "/proc/candela-report: cannot create the report folder"},
                      BadInput{"SkyboxBlurAboveOne", "render --skybox-blur 2 --out {dir}/x.png", "--skybox-blur: expected 0 (sharp) to 1, got '2'"},
                      BadInput{"ExposureNan", "render --exposure nan --out {dir}/x.png", "--exposure: expected a number, got 'nan'"},
                      BadInput{"DebugViewUnknown", "render --debug-view normals --out {dir}/x.png",
                               "--debug-view: expected none, base-color, geometric-normal, mapped-normal, roughness, "
                               "metallic, occlusion, emissive, d, g, f, diffuse, specular, clearcoat, clearcoat-normal, sheen, "
                               "anisotropy-direction, transmission, iridescence-thickness, iridescence-fresnel, "
                               "diffuse-transmission or dispersion, got 'normals'"},
                      BadInput{"ViewScreenshotWithoutFrames", "view --screenshot {dir}/x.png",
                               "--screenshot: also give --frames N (the frame to save; the viewer then exits)"},
                      BadInput{"ViewTwoScenes", "view a.glb b.glb", "unexpected argument 'b.glb': the scene is already a.glb"},
                      BadInput{"SoakZeroFrames", "soak --frames 0", "--frames: must be at least 1"},
                      BadInput{"TimeNegative", "render --time -1 --out {dir}/x.png", "--time: expected a number of seconds >= 0, got '-1'"},
                      BadInput{"TimeNotANumber", "render --time soon --out {dir}/x.png", "--time: expected a number of seconds >= 0, got 'soon'"},
                      BadInput{"AnimationEmptyItem", "render --animation 0,,1 --out {dir}/x.png", "--animation: expected indices, names, all or none, got '0,,1'"},
                      BadInput{"AnimationOfAStaticScene", "render --scene {dir}/triangle.gltf --animation 0 --out {dir}/x.png", "no animation 0 (the scene has no animations)"},
                      BadInput{"AnimationNameUnknown", "render --scene {dir}/triangle.gltf --animation Walk --out {dir}/x.png", "no animation named 'Walk' (the scene has no animations)"},
                      BadInput{"SequenceWithoutFrameNumber", "render --frames 3 --out {dir}/x.png", "--out {dir}/x.png: an image sequence needs exactly one %d or %0Nd for the frame number"},
                      BadInput{"SequenceTwoFrameNumbers", "render --frames 3 --out {dir}/x_%d_%d.png", "needs exactly one %d"},
                      BadInput{"SequenceBadField", "render --frames 3 --out {dir}/x_%s.png", "needs one %d or %0Nd for the frame number"},
                      BadInput{"FpsZero", "render --frames 3 --fps 0 --out {dir}/x_%d.png", "--fps: expected frames per second > 0, got '0'"},
                      BadInput{"SceneIndexBeyondTheFile", "render --scene {dir}/triangle.gltf --scene-index 3 --out {dir}/x.png", "scene 3 does not exist (the file has 1 scenes)"},
                      BadInput{"SceneIndexWithoutScene", "render --scene-index 1 --out {dir}/x.png", "--scene-index: give a glTF file with --scene"},
                      BadInput{"MemoryBudgetZero", "render --memory-budget 0 --out {dir}/x.png", "--memory-budget: need at least 1 MiB"},
                      // Geometry and shading options.
                      BadInput{"LodErrorNegative", "render --lod-error -1 --out {dir}/x.png", "--lod-error: expected pixels ≥ 0, got '-1'"},
                      BadInput{"LodMaybe", "render --lod maybe --out {dir}/x.png", "--lod: expected on or off, got 'maybe'"},
                      BadInput{"CullMaybe", "render --cull maybe --out {dir}/x.png", "--cull: expected on or off, got 'maybe'"},
                      BadInput{"SpecularAaMaybe", "render --specular-aa 1 --out {dir}/x.png", "--specular-aa: expected on or off, got '1'"},
                      BadInput{"GridZero", "bench --grid 0", "--grid: expected 1 to 1000 spheres a side, got '0'"},
                      BadInput{"GridWithScene", "render --grid 3 --scene {dir}/triangle.gltf --out {dir}/x.png", "--grid: sizes the built-in sphere grid; not with --scene"},
                      BadInput{"ScaleReportSizeZero", "scale-report --sizes 1,0 --out {dir}/r", "--sizes: expected grid sides from 1 to 1000, got '1,0'"},
                      BadInput{"ScaleReportUnwritableOut", "scale-report --out /proc/candela-report", "/proc/candela-report: cannot create the report folder"},
                      BadInput{"MsaaThree", "render --msaa 3 --out {dir}/x.png", "--msaa: expected 1, 2, 4 or 8, got '3'"},
                      BadInput{"QualityReportMsaaSixteen", "quality-report --msaa 1,16 --out {dir}/r", "--msaa: expected 1, 2, 4 or 8, got '16'"},
                      BadInput{"QualityReportNegativeLodError", "quality-report --lod-errors 0,-2 --out {dir}/r", "--lod-errors: expected pixels ≥ 0, got '0,-2'"},
                      BadInput{"QualityReportMissingScene", "quality-report --scenes default,{dir}/missing.glb --out {dir}/r", "{dir}/missing.glb"},
                      BadInput{"QualityReportSameSceneTwice", "quality-report --scenes default,default --out {dir}/r", "--scenes: two scenes named 'default'"},
                      BadInput{"QualityReportEnvNone", "quality-report --env none --out {dir}/r", "--env: quality-report needs an environment (an .hdr/.exr file or sky)"}),
    [](const ::testing::TestParamInfo<BadInput>& row) { return std::string(row.param.name); });

TEST(Cli, HelpExitsZero) { EXPECT_EQ(run("--help").exitCode, 0); }

TEST(Cli, CommandHelpListsThatCommandsFlagsOnly) {
    const Result render = run("render --help");
    EXPECT_EQ(render.exitCode, 0);
    EXPECT_EQ(render.stderrText, "");
    EXPECT_EQ(render.stdoutText.rfind("usage: candela render", 0), 0u) << render.stdoutText;
    EXPECT_NE(render.stdoutText.find("\n  --graph-json FILE"), std::string::npos);
    EXPECT_EQ(render.stdoutText.find("--screenshot"), std::string::npos);
    const Result view = run("view -h");
    EXPECT_EQ(view.exitCode, 0);
    EXPECT_NE(view.stdoutText.find("\n  --screenshot FILE"), std::string::npos);
    EXPECT_EQ(view.stdoutText.find("--graph-json"), std::string::npos);
}

TEST(Cli, VersionIsTheProjects) {
    const Result r = run("--version");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.stdoutText, "candela " CANDELA_PROJECT_VERSION "\n");
    EXPECT_EQ(r.stderrText, "");
}

TEST(Cli, RejectedFlagsWriteNothing) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "candela_cli_rejected";
    std::filesystem::create_directories(dir);
    EXPECT_EQ(run("bench --graph-json " + (dir / "g.json").string() + " --out " + (dir / "x.png").string() + " --explain").exitCode, 2);
    EXPECT_EQ(run("view --graph-dot " + (dir / "g.dot").string() + " --explain").exitCode, 2);
    EXPECT_TRUE(std::filesystem::is_empty(dir));
    std::filesystem::remove_all(dir);
}

TEST(Cli, ImageSequenceWritesOneFilePerFrame) {
    const std::filesystem::path model = ::candela::test::sharedAssets() / "models/BoxAnimated/glTF-Binary/BoxAnimated.glb";
    if (!std::filesystem::exists(model)) GTEST_SKIP() << "shared asset missing";
    const auto dir = tempDir();
    const Result r = run("render --env none --validate --width 48 --height 36 --frames 3 --fps 2 --turntable 90 --scene " +
                         model.string() + " --out " + (dir / "box_%03d.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    std::vector<std::string> frames;
    for (const char* name : {"box_000.png", "box_001.png", "box_002.png"}) {
        std::ifstream in(dir / name, std::ios::binary);
        frames.emplace_back((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_FALSE(frames.back().empty()) << name;
    }
    EXPECT_NE(frames[0], frames[1]);
    EXPECT_NE(frames[1], frames[2]);
    EXPECT_FALSE(std::filesystem::exists(dir / "box_003.png"));
    EXPECT_NE(r.stdoutText.find("t = 1.0000 s"), std::string::npos) << r.stdoutText;  // frame 2 at 2 fps
    std::filesystem::remove_all(dir);
}

TEST(Cli, TimeAndAnimationChooseThePose) {
    const std::filesystem::path model = ::candela::test::sharedAssets() / "models/BoxAnimated/glTF-Binary/BoxAnimated.glb";
    if (!std::filesystem::exists(model)) GTEST_SKIP() << "shared asset missing";
    const auto dir = tempDir();
    const auto render = [&](const std::string& flags, const std::string& name) {
        const std::filesystem::path out = dir / name;
        const Result r = run("render --env none --validate --width 64 --height 48 --camera-orbit 30,70,5 --target 0,1.3,0 --scene " +
                             model.string() + " " + flags + " --out " + out.string());
        EXPECT_EQ(r.exitCode, 0) << r.stderrText;
        EXPECT_EQ(r.stderrText, "");
        std::ifstream in(out, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    const std::string start = render("", "start.png");
    ASSERT_FALSE(start.empty());
    // The default is animation 0 at time 0; a time later it has moved; one loop later it is back.
    EXPECT_EQ(render("--animation 0 --time 0", "zero.png"), start);
    const std::string later = render("--time 1.875", "later.png");
    EXPECT_NE(later, start);
    EXPECT_EQ(render("--time 5.583329916000366", "looped.png"), render("--time 1.875 --animation all", "again.png"));
    // none: the rest pose, which differs from the pose at 1.875 s.
    EXPECT_NE(render("--animation none --time 1.875", "rest.png"), later);
    std::filesystem::remove_all(dir);
}

// A device-memory budget too small for anything is one line naming the resource and exit code 4;
// one too small only for the default IBL maps lowers their resolution (and the environment's) with
// a warning.
TEST(Cli, MemoryBudgetExhaustedOrDegraded) {
    const std::filesystem::path png = tempDir() / "budget.png";
    const Result tiny = run("render --memory-budget 1 --width 64 --height 36 --out " + png.string());
    EXPECT_EQ(tiny.exitCode, 4) << tiny.stderrText;
    EXPECT_EQ(tiny.stderrText.find('\n'), tiny.stderrText.size() - 1) << tiny.stderrText;
    EXPECT_NE(tiny.stderrText.find("candela: error: out of device memory: cannot allocate "), std::string::npos) << tiny.stderrText;
    EXPECT_NE(tiny.stderrText.find("the device-memory budget of 1.0 MiB is exhausted"), std::string::npos) << tiny.stderrText;
    EXPECT_FALSE(std::filesystem::exists(png));

    // 6 MiB: the specular cube (4 MiB at 256 texels) fails first, then the upload of the
    // environment; each step halves the cube and the environment's upload.
    const Result small = run("render --validate --memory-budget 6 --width 64 --height 36 --out " + png.string());
    EXPECT_EQ(small.exitCode, 0) << small.stderrText;
    EXPECT_NE(small.stderrText.find("cannot allocate 4.0 MiB for image 'ibl_specular'"), std::string::npos) << small.stderrText;
    EXPECT_NE(small.stderrText.find("lowering the environment cube to 64 texels and the environment to at most 256 texels a side"),
              std::string::npos)
        << small.stderrText;
    EXPECT_EQ(small.stderrText.find("validation"), std::string::npos) << small.stderrText;
    EXPECT_TRUE(std::filesystem::exists(png));
}

TEST(Cli, RenderWritesPngAndGraphExports) {
    const auto dir = tempDir();
    const auto png = dir / "frame.png", json = dir / "graph.json", dot = dir / "graph.dot";
    const Result r = run("render --env none --validate --width 40 --height 30 --out " + png.string() +
                         " --graph-json " + json.string() + " --graph-dot " + dot.string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load(png.c_str(), &w, &h, &channels, 4);
    ASSERT_NE(pixels, nullptr);
    stbi_image_free(pixels);
    EXPECT_EQ(w, 40);
    EXPECT_EQ(h, 30);

    std::ifstream in(json);
    const nlohmann::json graph = nlohmann::json::parse(in);
    ASSERT_EQ(graph["order"].size(), 3u);
    // The default scene's frame graph without an environment: forward → tonemap → readback.
    EXPECT_EQ(graph["order"][0], "forward");
    EXPECT_EQ(graph["order"][1], "tonemap");
    EXPECT_EQ(graph["order"][2], "readback");
    std::ifstream dotIn(dot);
    const std::string dotText((std::istreambuf_iterator<char>(dotIn)), std::istreambuf_iterator<char>());
    EXPECT_NE(dotText.find("digraph"), std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST(Cli, FloatOutputsCullTheTonemapPass) {
    const auto dir = tempDir();
    for (const char* name : {"frame.exr", "frame.pfm"}) {
        const auto out = dir / name, json = dir / "graph.json";
        // Specular AA off: at this size it would spread the sub-pixel highlights below 1.
        const Result r = run("render --env none --validate --specular-aa off --width 96 --height 64 --out " + out.string() +
                             " --graph-json " + json.string());
        ASSERT_EQ(r.exitCode, 0) << r.stderrText;
        if (out.extension() == ".pfm") {
            EXPECT_EQ(std::filesystem::file_size(out), std::string("PF\n96 64\n-1.0\n").size() + 96u * 64u * 12u);
        } else {
            // Read back with OpenEXR's C++ library (Candela's own reader drops alpha).
            Imf::RgbaInputFile file(out.c_str());
            const Imath::Box2i window = file.dataWindow();
            const int w = window.max.x - window.min.x + 1, h = window.max.y - window.min.y + 1;
            std::vector<Imf::Rgba> pixels(size_t(w) * size_t(h));
            file.setFrameBuffer(pixels.data() - window.min.x - window.min.y * w, 1, size_t(w));
            file.readPixels(window.min.y, window.max.y);
            std::vector<float> rgba;
            for (const Imf::Rgba& p : pixels) rgba.insert(rgba.end(), {float(p.r), float(p.g), float(p.b), float(p.a)});
            EXPECT_EQ(w, 96);
            EXPECT_EQ(h, 64);
            // The HDR image: background pixels have coverage 0; the lit spheres have coverage 1
            // and radiance (specular highlights of 300 cd lights) beyond 1.
            EXPECT_FLOAT_EQ(rgba[3], 0.0f);
            float maxValue = 0.0f, maxAlpha = 0.0f;
            for (int i = 0; i < w * h * 4; ++i) {
                if (i % 4 == 3) maxAlpha = std::max(maxAlpha, rgba[i]);
                else maxValue = std::max(maxValue, rgba[i]);
            }
            EXPECT_FLOAT_EQ(maxAlpha, 1.0f);
            EXPECT_GT(maxValue, 1.0f);
        }
        std::ifstream in(json);
        const nlohmann::json graph = nlohmann::json::parse(in);
        bool sawCulledTonemap = false;
        for (const auto& pass : graph["passes"])
            if (pass["name"] == "tonemap") sawCulledTonemap = pass["culled"].get<bool>();
        EXPECT_TRUE(sawCulledTonemap);
    }
    std::filesystem::remove_all(dir);
}

TEST(Cli, BenchReportsFrameAndPassesAsRatiosToCalibration) {
    const std::string command = candela::test::candelaExecutable() + " bench --validate --frames 2 --width 48 --height 32 --json --explain";
    FILE* pipe = popen(command.c_str(), "r");
    std::string out;
    std::array<char, 4096> buffer;
    while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
    ASSERT_EQ(pclose(pipe), 0) << out;
    const nlohmann::json report = nlohmann::json::parse(out);
    EXPECT_EQ(report["frames"], 2);
    EXPECT_GT(report["calibration"]["medianMs"].get<double>(), 0.0);
    const double ratio = report["frame"]["medianRatio"].get<double>();
    EXPECT_NEAR(ratio, report["frame"]["medianMs"].get<double>() / report["calibration"]["medianMs"].get<double>(), 1e-9);
    // Measured frames come after the warm-up, which ran the IBL precompute: they hold none.
    // The sky is composited by the tonemap.
    ASSERT_EQ(report["passes"].size(), 2u);
    EXPECT_EQ(report["passes"][0]["name"], "forward");
    EXPECT_EQ(report["passes"][1]["name"], "tonemap");
    // Each pass also run alone (submitted and waited for by itself): a wall time for every one.
    for (const auto& pass : report["passes"]) {
        EXPECT_GT(pass["serialMedianMs"].get<double>(), 0.0) << pass["name"];
        EXPECT_LE(pass["serialP25Ms"].get<double>(), pass["serialMedianMs"].get<double>()) << pass["name"];
        EXPECT_GE(pass["serialP75Ms"].get<double>(), pass["serialMedianMs"].get<double>()) << pass["name"];
        EXPECT_NEAR(pass["serialRatio"].get<double>(),
                    pass["serialMedianMs"].get<double>() / report["calibration"]["medianMs"].get<double>(), 1e-9);
    }
    // The frame times' spread (interquartile range) around their median.
    EXPECT_LE(report["frame"]["p25Ms"].get<double>(), report["frame"]["medianMs"].get<double>());
    EXPECT_GE(report["frame"]["p75Ms"].get<double>(), report["frame"]["medianMs"].get<double>());
    // lavapipe is a CPU device: its timestamps miss deferred work, and the report says so.
    if (report["device"].get<std::string>().find("llvmpipe") != std::string::npos) {
        EXPECT_NE(report.value("gpuMsUnreliable", "").find("unreliable on lavapipe"), std::string::npos) << out;
    }
    // Both shading paths measured, each with its passes.
    ASSERT_EQ(report["shadingPaths"].size(), 2u);
    for (const auto& path : report["shadingPaths"]) {
        ASSERT_FALSE(path["passes"].empty()) << path["path"];
        for (const auto& pass : path["passes"]) EXPECT_GT(pass["serialMedianMs"].get<double>(), 0.0) << pass["name"];
    }
    // --explain: of the measured frames (not of a calibration run), in the JSON.
    ASSERT_TRUE(report["explain"].is_array());
    EXPECT_FALSE(report["explain"].empty());
}

// The sky's cost measured by leaving it out: the debug-view switch bench runs afterwards draws no
// skybox pass, which is no reason to fail.
TEST(Cli, BenchWithoutTheSkybox) {
    const Result r = run("bench --validate --frames 1 --width 48 --height 32 --shading-path forward --disable-pass skybox");
    EXPECT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_NE(r.stdoutText.find("pass tonemap"), std::string::npos) << r.stdoutText;
    EXPECT_EQ(run("bench --frames 1 --width 48 --height 32 --disable-pass skybx").exitCode, 2);
}

TEST(Cli, DefaultRenderIsLitByTheProceduralSkyWithPrecomputeFirst) {
    const auto dir = tempDir();
    const auto png = dir / "frame.png", json = dir / "graph.json";
    const Result r = run("render --validate --explain --width 40 --height 30 --out " + png.string() + " --graph-json " +
                         json.string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    std::ifstream in(json);
    const nlohmann::json graph = nlohmann::json::parse(in);
    std::vector<std::string> order;
    for (const auto& name : graph["order"]) order.push_back(name.get<std::string>());
    auto position = [&](const std::string& name) {
        return static_cast<size_t>(std::find(order.begin(), order.end(), name) - order.begin());
    };
    ASSERT_EQ(order.size(), 7u) << graph["order"].dump();
    for (const char* precompute : {"ibl_brdf_lut", "ibl_cubemap", "ibl_prefilter", "ibl_irradiance_cube"})
        EXPECT_LT(position(precompute), position("forward")) << precompute;
    EXPECT_LT(position("ibl_cubemap"), position("ibl_prefilter"));
    EXPECT_LT(position("ibl_cubemap"), position("ibl_irradiance_cube"));
    // The sky is composited by the tonemap, right after the forward pass.
    EXPECT_EQ(position("tonemap"), position("forward") + 1);
    EXPECT_NE(r.stdoutText.find("sky: composited by the tonemap where nothing was drawn"), std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("ibl: environment 'procedural sky'"), std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("ibl: maps computed by this frame's precompute passes"), std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("left out: SH9 projection"), std::string::npos) << r.stdoutText;
    // On a CPU device (lavapipe; bench's test checks the device) per-pass timestamps miss deferred
    // work: the times are marked in the line and the reason said once; the graph export says so too.
    const bool marked = r.stdoutText.find(" ms GPU*") != std::string::npos;
    EXPECT_EQ(marked, graph.contains("gpuMsUnreliable")) << r.stdoutText;
    const std::string note = "* per-pass GPU times are unreliable on lavapipe";
    EXPECT_EQ(r.stdoutText.find(note) != std::string::npos, marked) << r.stdoutText;
    EXPECT_EQ(r.stdoutText.find(note), r.stdoutText.rfind(note)) << "said once";
    std::filesystem::remove_all(dir);
}

TEST(Cli, IblReportWritesTablesAndPlotsWithTheDefaultMarked) {
    const auto dir = tempDir() / "ibl-report";
    const Result r = run("ibl-report --quick --repeats 2 --width 32 --height 18 --reference-samples 64 --out " +
                         dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    for (const char* file : {"report.csv", "report.md", "specular.png", "irradiance.png", "lut.png", "image.png",
                             "ground_truth.exr", "default.png"})
        EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
    std::ifstream csv(dir / "report.csv");
    std::string header, line;
    std::getline(csv, header);
    EXPECT_NE(header.find("precompute_ms"), std::string::npos);
    EXPECT_NE(header.find("rmse_r0.14"), std::string::npos) << "errors per roughness level (8 levels: 1/7)";
    // The ratio to calibration: the median of the rounds, within their lowest and highest.
    std::vector<std::string> columns;
    std::stringstream headerStream(header);
    for (std::string cell; std::getline(headerStream, cell, ',');) columns.push_back(cell);
    const auto column = [&](const char* name) { return size_t(std::find(columns.begin(), columns.end(), name) - columns.begin()); };
    const size_t ratio = column("ratio_to_calibration"), low = column("ratio_min"), high = column("ratio_max");
    ASSERT_LT(std::max({ratio, low, high}), columns.size()) << header;
    size_t rows = 0, checked = 0;
    while (std::getline(csv, line)) {
        ++rows;
        EXPECT_EQ(line.find("nan"), std::string::npos) << line;
        EXPECT_EQ(line.find("inf"), std::string::npos) << line;
        // Cells after the quoted group name hold no commas.
        std::vector<std::string> cells{line.substr(0, line.find("\",") + 1)};
        std::stringstream cellStream(line.substr(cells[0].size() + 1));
        for (std::string cell; std::getline(cellStream, cell, ',');) cells.push_back(cell);
        // Rows whose label holds commas, or with another number of roughness levels, are skipped.
        if (cells.size() != columns.size()) continue;
        ++checked;
        EXPECT_LE(std::stod(cells[low]), std::stod(cells[ratio])) << line;
        EXPECT_GE(std::stod(cells[high]), std::stod(cells[ratio])) << line;
    }
    EXPECT_GE(rows, 7u);
    EXPECT_GE(checked, 1u);
    std::ifstream md(dir / "report.md");
    const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("(default)"), std::string::npos);
    int w = 0, h = 0, channels = 0;
    stbi_uc* plot = stbi_load((dir / "specular.png").c_str(), &w, &h, &channels, 4);
    ASSERT_NE(plot, nullptr);
    stbi_image_free(plot);
    EXPECT_EQ(w, 960);
    std::filesystem::remove_all(dir);
}

TEST(Cli, ScaleReportSweepsGridSizesWithLevelsOfDetailOnAndOff) {
    const auto dir = tempDir() / "scale-report";
    const Result r = run("scale-report --validate --sizes 1,3 --frames 1 --width 64 --height 36 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    for (const char* file : {"report.csv", "report.md", "frame_vs_triangles.png"}) EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
    std::ifstream csv(dir / "report.csv");
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header.rfind("side,lod_error_px,scene_draws,submitted_draws,culled_draws,scene_triangles,submitted_triangles", 0), 0u);
    std::vector<std::vector<std::string>> rows;
    while (std::getline(csv, line)) {
        std::vector<std::string>& row = rows.emplace_back();
        for (size_t start = 0;;) {
            const size_t comma = line.find(',', start);
            row.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    }
    // 1 and 3, levels of detail on (1 px) and off, each on the forward and the visibility path.
    ASSERT_EQ(rows.size(), 8u);
    EXPECT_EQ(rows[4][0], "3");
    EXPECT_EQ(rows[4][2], "9");                       // draws
    EXPECT_EQ(std::stoull(rows[4][5]), 9ull * 3968);  // 64 × 32 spheres: 64 × (2 · 32 − 2) triangles
    EXPECT_EQ(rows[4].back(), "forward");
    EXPECT_EQ(rows[5].back(), "visibility");
    EXPECT_EQ(rows[5][6], rows[4][6]);                // the same draws on both paths
    EXPECT_EQ(rows[6][1], "0");
    EXPECT_EQ(rows[6][6], rows[6][5]);                // off: every triangle
    EXPECT_LT(std::stoull(rows[4][6]), std::stoull(rows[4][5]) / 10);  // on, 64 × 36 pixels: the coarsest levels
    EXPECT_NE(r.stderrText.find("scale-report: 8/8"), std::string::npos) << r.stderrText;
    std::filesystem::remove_all(dir);
}

TEST(Cli, QualityReportSweepsMsaaSpecularAaAndLevelsOfDetail) {
    // A reduced sweep on the built-in grid: every setting a row with its error and temporal
    // difference, the device's clamp of --msaa 2 noted, the default ringed in the plots. LOD 0 is
    // asked twice: the same work and images, so one row ("0/0") per series.
    const auto dir = tempDir() / "quality-report";
    const Result r = run("quality-report --validate --msaa 1,2,4 --lod-errors 0,0.5,0 --frames 1 --repeats 2 --orbit-frames 2 "
                         "--width 64 --height 36 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    for (const char* file : {"report.csv", "report.md", "default_error.png", "default_temporal.png"})
        EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
    std::ifstream csv(dir / "report.csv");
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header.rfind("scene,msaa,specular_aa,lod_error_px,shading_path,frame_ratio,frame_ratio_min,frame_ratio_max,"
                           "frame_ms,mean_error,p99_error,temporal", 0), 0u) << header;
    size_t rows = 0, defaults = 0, settings = 0, zeroTwice = 0;
    while (std::getline(csv, line)) {
        ++rows;
        defaults += line.back() == '1';
        std::vector<std::string> cells;
        std::stringstream cellStream(line);
        for (std::string cell; std::getline(cellStream, cell, ',');) cells.push_back(cell);
        ASSERT_GE(cells.size(), 8u) << line;
        const std::string& lod = cells[3];
        settings += 1 + std::count(lod.begin(), lod.end(), '/');
        zeroTwice += lod.rfind("0/", 0) == 0 && lod.find("/0", 1) != std::string::npos;
        // The median ratio lies within the lowest and highest round.
        EXPECT_LE(std::stod(cells[6]), std::stod(cells[5])) << line;
        EXPECT_GE(std::stod(cells[7]), std::stod(cells[5])) << line;
    }
    // lavapipe renders 1 and 4 samples: 2 is clamped to 1 and not measured twice; each setting on
    // the forward and the visibility path.
    constexpr size_t kSeries = 2 * 2 * 2;
    EXPECT_EQ(settings, kSeries * 3);
    EXPECT_EQ(zeroTwice, kSeries);
    EXPECT_LE(rows, kSeries * 2);
    EXPECT_EQ(defaults, 1u);
    std::ifstream md(dir / "report.md");
    const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("MSAA 2: not supported here"), std::string::npos) << text;
    EXPECT_NE(text.find("★"), std::string::npos);
    // The reference, each setting's orbit, each setting in each of the 2 timing rounds.
    EXPECT_NE(r.stderrText.find("quality-report: 73/73"), std::string::npos) << r.stderrText;
    std::filesystem::remove_all(dir);
}

// `candela info` through a device profile: the variable names it, the flag wins over the
// variable, and an unknown name in either is a one-line error with exit code 2.
TEST(Cli, InfoUnderADeviceProfileListsItsLimitsAndFallbacks) {
    const auto capture = [](const std::string& prefix, const std::string& args, int* status) {
        const std::string command = prefix + " " + candela::test::candelaExecutable() + " info " + args + " 2>&1";
        FILE* pipe = popen(command.c_str(), "r");
        std::string out;
        std::array<char, 4096> buffer;
        while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
        *status = pclose(pipe);
        return out;
    };
    int status = 0;
    const std::string minimum = capture("CANDELA_DEVICE_PROFILE=minimum", "", &status);
    EXPECT_EQ(status, 0) << minimum;
    for (const char* line : {"device profile: minimum (Vulkan 1.3 specification",
                             "per-stage limits: 16 samplers, 16 sampled images, 4 storage buffers, 4 storage images",
                             "environment cube: R16G16B16A16_SFLOAT instead of R32G32B32A32_SFLOAT (no SAMPLED_IMAGE_FILTER_LINEAR)",
                             "sheen LUT: R16G16B16A16_SFLOAT instead of R32_SFLOAT",
                             "BRDF LUT: R16G16B16A16_SFLOAT instead of R16G16_SFLOAT (no STORAGE_IMAGE)",
                             "layered materials: a program per layer combination"})
        EXPECT_NE(minimum.find(line), std::string::npos) << line << "\n" << minimum;
    const std::string native = capture("CANDELA_DEVICE_PROFILE=minimum", "--device-profile native", &status);
    EXPECT_EQ(status, 0) << native;
    EXPECT_NE(native.find("device profile: native"), std::string::npos) << native;
    const std::string badVariable = capture("CANDELA_DEVICE_PROFILE=tiny", "", &status);
    EXPECT_EQ(WEXITSTATUS(status), 2) << badVariable;
    EXPECT_EQ(badVariable, "candela: error: CANDELA_DEVICE_PROFILE=tiny: no such device profile (profiles: native, minimum, "
                           "desktop, apple)\n");
    const Result badFlag = run("info --device-profile tiny");
    EXPECT_EQ(badFlag.exitCode, 2);
    EXPECT_EQ(badFlag.stderrText, "candela: error: --device-profile: no device profile 'tiny' (profiles: native, minimum, "
                                  "desktop, apple)\n");
}

TEST(Cli, InfoListsDevicesAndTheChoice) {
    const std::string command = candela::test::candelaExecutable() + " info 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    std::string out;
    std::array<char, 4096> buffer;
    while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
    EXPECT_EQ(pclose(pipe), 0);
    EXPECT_NE(out.find("chosen:"), std::string::npos) << out;
    EXPECT_NE(out.find("why:"), std::string::npos) << out;
    EXPECT_NE(out.find("features enabled: dynamicRendering synchronization2 maintenance4"), std::string::npos) << out;
    // The MSAA default of the chosen device and why (1 on CPU devices such as lavapipe, 4 on GPUs).
    EXPECT_TRUE(out.find("MSAA: 1 sample (no MSAA) (default on CPU devices") != std::string::npos ||
                out.find("MSAA: 4 samples (default on GPUs") != std::string::npos)
        << out;
}

}  // namespace
