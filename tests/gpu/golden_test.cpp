// Golden-image tests: the default scene and glTF sample models rendered on lavapipe with the
// validation layer on — lit by their lights, or by an environment (image-based lighting at the
// default quality, skybox behind) — compared with approved images in tests/golden/.
//
// Metric (stated once, applied to every case): a pixel differs when any RGBA channel differs by
// more than 3 levels (of 255); a case fails when more than 0.1% of its pixels differ or any channel
// differs by more than 24 levels. lavapipe is deterministic on one machine; the slack absorbs LLVM
// code generation differences between CPUs.
//
// On another driver (SwiftShader, the suite's second device: docs/devices.md; a GPU in the GPU
// check) the approved lavapipe images are compared by LDR-ꟻLIP: a case fails when the mean exceeds
// 0.03. Another implementation moves silhouettes (SwiftShader snaps vertices to 1/16 of a pixel,
// lavapipe to 1/256: edge pixels differ by up to 228 levels), filters textures with its own LOD
// arithmetic (text edges in TextureSettingsTest) and rounds small specular highlights otherwise,
// which the per-level metric cannot tell from an error. Measured: on SwiftShader mean ꟻLIP up to
// 0.0226 (ibl_specular_test; 0.0151 at most lit without an environment), on the NVIDIA H200 of the
// GPU check's first run up to 0.0268 (ibl_transmission_test).
//
// On failure, or when a golden is missing, the render and an amplified difference image are
// written to ${build}/tests/gpu/golden_out/ (CANDELA_GOLDEN_OUT in the environment moves it);
// tools/approve-goldens.sh copies renders you have looked at into tests/golden/. With
// CANDELA_GOLDEN_KEEP=1 every render is written, passing or not: NAME.actual.png (the default
// path) and NAME.visibility.png (ShadingPathsAgree) — tools/gpu-check.sh compares them with the
// approved images by ꟻLIP on a machine whose driver is not lavapipe.

#include "gpu_test.h"
#include "test_paths.h"
#include "compressed_test_util.h"

#include "assets/builtin_scenes.h"
#include "assets/gltf_loader.h"
#include "assets/image_file.h"
#include "assets/procedural_sky.h"
#include "pose/scene_pose.h"
#include "render/renderer.h"
#include "scene/framing.h"
#include "scene/material_variants.h"
#include "reports/flip.h"
#include "shared/tonemap.h"

#include <stb_image.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace candela::test::golden_test {
namespace {

struct GoldenCase {
    const char* name;
    const char* model;  // path under ../shared/assets/models, or "" for the built-in sphere grid
    glm::vec3 orbit{0.0f, 90.0f, 0.0f};  // θ°, φ°, r (0: frame the bounds)
    // Image-based lighting: "" none (the scene's or the default lights), "sky" the procedural sky,
    // else a file under ../shared/assets/environments, shown as the skybox, without default lights.
    const char* environment = "";
    float environmentRotation = 0.0f;
    // Animated models: the animations to play (as --animation: "0", "all", a name; "" the default)
    // and the time, seconds.
    const char* animation = "";
    double time = 0.0;
    const char* variant = "";  // KHR_materials_variants: the variant to draw ("" the default materials)
    // The level-of-detail error, pixels (--lod-error). The goldens pin the shading, so they draw
    // full detail (0) but for the *_lod cases, which pin the default; how far levels of detail
    // may move an image is measured against full detail by lod_test.cpp.
    float lodError = 0.0f;
    // A camera given whole (with orbit's r > 0): the target and the field of view; none: framing's.
    std::optional<glm::vec3> target;
    std::optional<float> fovYDegrees;
};

constexpr uint32_t kWidth = 256, kHeight = 192;
constexpr int kPixelThreshold = 3;
constexpr int kMaxDifference = 24;
constexpr double kMaxDifferingShare = 0.001;
constexpr double kOtherDriverMaxFlipMean = 0.03;

// LDR-ꟻLIP mean of two kWidth × kHeight RGBA8 sRGB images (alpha ignored).
double flipMean(const uint8_t* actual, const uint8_t* expected) {
    auto linear = [](const uint8_t* rgba) {
        reports::RgbImage image{kWidth, kHeight, std::vector<float>(size_t(kWidth) * kHeight * 3)};
        for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i)
            for (size_t c = 0; c < 3; ++c) image.rgb[3 * i + c] = reports::srgbToLinear(rgba[4 * i + c]);
        return image;
    };
    return reports::flipStatistics(reports::ldrFlip(linear(expected), linear(actual), reports::pixelsPerDegree({}))).mean;
}

const GoldenCase kCases[] = {
    {"default_scene", ""},
    // The default level-of-detail error (options::DrawSelection::kDefaultLodErrorPixels): at this
    // size the spheres are drawn at coarser tessellations and the helmet at a simplified level.
    {"default_scene_lod", "", {0.0f, 90.0f, 0.0f}, "", 0.0f, "", 0.0, "", options::DrawSelection::kDefaultLodErrorPixels},
    {"ibl_damaged_helmet_lod", "DamagedHelmet/glTF-Binary/DamagedHelmet.glb", {-30.0f, 80.0f, 0.0f}, "studio_small_03_1k.hdr",
     0.0f, "", 0.0, "", options::DrawSelection::kDefaultLodErrorPixels},
    {"damaged_helmet", "DamagedHelmet/glTF-Binary/DamagedHelmet.glb", {-30.0f, 80.0f, 0.0f}},
    {"metal_rough_spheres", "MetalRoughSpheresNoTextures/glTF/MetalRoughSpheresNoTextures.gltf"},
    {"normal_tangent", "NormalTangentTest/glTF/NormalTangentTest.gltf"},
    {"normal_tangent_mirror", "NormalTangentMirrorTest/glTF/NormalTangentMirrorTest.gltf"},
    {"alpha_blend_mode", "AlphaBlendModeTest/glTF-Binary/AlphaBlendModeTest.glb"},
    {"texture_settings", "TextureSettingsTest/glTF/TextureSettingsTest.gltf"},
    {"orientation", "OrientationTest/glTF/OrientationTest.gltf", {20.0f, 70.0f, 0.0f}},
    {"negative_scale", "NegativeScaleTest/glTF-Binary/NegativeScaleTest.glb"},
    {"vertex_color", "VertexColorTest/glTF/VertexColorTest.gltf"},
    {"texture_transform", "TextureTransformTest/glTF/TextureTransformTest.gltf"},
    {"emissive_strength", "EmissiveStrengthTest/glTF-Binary/EmissiveStrengthTest.glb"},
    {"mesh_primitive_modes", "MeshPrimitiveModes/glTF/MeshPrimitiveModes.gltf"},
    {"triangle_without_indices", "TriangleWithoutIndices/glTF/TriangleWithoutIndices.gltf"},
    {"unlit", "UnlitTest/glTF/UnlitTest.gltf"},
    {"ibl_damaged_helmet", "DamagedHelmet/glTF-Binary/DamagedHelmet.glb", {-30.0f, 80.0f, 0.0f}, "studio_small_03_1k.hdr"},
    {"ibl_metal_rough_spheres", "MetalRoughSpheresNoTextures/glTF/MetalRoughSpheresNoTextures.gltf",
     {0.0f, 90.0f, 0.0f}, "venice_sunset_1k.hdr", 90.0f},
    {"ibl_default_scene_studio", "", {0.0f, 90.0f, 0.0f}, "studio_small_03_1k.hdr"},
    {"ibl_default_scene_venice", "", {0.0f, 90.0f, 0.0f}, "venice_sunset_1k.hdr", 180.0f},
    {"ibl_default_scene_sky", "", {0.0f, 90.0f, 0.0f}, "sky"},
    // Node animation (rigid): rotation (LINEAR quaternions), translation and a hierarchy, and the
    // three interpolation modes side by side between their keys.
    {"animated_cube_t0_75", "AnimatedCube/glTF/AnimatedCube.gltf", {30.0f, 70.0f, 0.0f}, "", 0.0f, "", 0.75},
    {"box_animated_t1_875", "BoxAnimated/glTF-Binary/BoxAnimated.glb", {30.0f, 80.0f, 0.0f}, "", 0.0f, "", 1.875},
    // Skins (the joints place the vertices in world space) and morph targets, through skin_morph.
    {"cesium_man_t1_1", "CesiumMan/glTF-Binary/CesiumMan.glb", {30.0f, 80.0f, 0.0f}, "", 0.0f, "", 1.1},
    {"fox_survey_t1_5", "Fox/glTF-Binary/Fox.glb", {40.0f, 75.0f, 0.0f}, "", 0.0f, "Survey", 1.5},
    {"fox_run_t0_4", "Fox/glTF-Binary/Fox.glb", {40.0f, 75.0f, 0.0f}, "", 0.0f, "Run", 0.4},
    {"animated_morph_cube_t1_6", "AnimatedMorphCube/glTF-Binary/AnimatedMorphCube.glb", {30.0f, 70.0f, 0.0f}, "", 0.0f, "", 1.6},
    {"morph_stress_test_t0_6", "MorphStressTest/glTF-Binary/MorphStressTest.glb", {0.0f, 70.0f, 0.0f}, "", 0.0f, "TheWave", 0.6},
    // EXT_mesh_gpu_instancing: 125 rotated and scaled cubes in one instanced draw.
    {"simple_instancing", "SimpleInstancing/glTF-Binary/SimpleInstancing.glb", {30.0f, 70.0f, 0.0f}},
    // KHR_draco_mesh_compression, and the same model uncompressed (DracoRendersLikeThePlainFile
    // compares the two).
    {"cesium_milk_truck", "CesiumMilkTruck/glTF-Binary/CesiumMilkTruck.glb", {30.0f, 75.0f, 0.0f}},
    {"cesium_milk_truck_draco", "CesiumMilkTruck/glTF-Draco/CesiumMilkTruck.gltf", {30.0f, 75.0f, 0.0f}},
    {"ibl_specular_test", "SpecularTest/glTF-Binary/SpecularTest.glb", {0.0f, 90.0f, 0.0f}, "studio_small_03_1k.hdr"},
    // KHR_materials_clearcoat: base, coated and coating-only columns; plain, textured (partial),
    // rough and normal-mapped coats.
    {"ibl_clearcoat_test", "ClearCoatTest/glTF-Binary/ClearCoatTest.glb", {0.0f, 90.0f, 0.0f}, "studio_small_03_1k.hdr"},
    // KHR_materials_sheen: fabric with a sheen over wood (no sheen).
    {"ibl_sheen_chair", "SheenChair/glTF/SheenChair.gltf", {20.0f, 60.0f, 0.0f}, "studio_small_03_1k.hdr"},
    // KHR_materials_anisotropy: strength and rotation, textured and not.
    {"ibl_anisotropy_rotation_test", "AnisotropyRotationTest/glTF-Binary/AnisotropyRotationTest.glb", {0.0f, 90.0f, 0.0f},
     "studio_small_03_1k.hdr"},
    // KHR_materials_variants: the shoe's three variants (the file's default is the first).
    {"ibl_variants_shoe_midnight", "MaterialsVariantsShoe/glTF/MaterialsVariantsShoe.gltf", {20.0f, 60.0f, 0.0f},
     "studio_small_03_1k.hdr", 0.0f, "", 0.0, "midnight"},
    {"ibl_variants_shoe_beach", "MaterialsVariantsShoe/glTF/MaterialsVariantsShoe.gltf", {20.0f, 60.0f, 0.0f},
     "studio_small_03_1k.hdr", 0.0f, "", 0.0, "beach"},
    {"ibl_variants_shoe_street", "MaterialsVariantsShoe/glTF/MaterialsVariantsShoe.gltf", {20.0f, 60.0f, 0.0f},
     "studio_small_03_1k.hdr", 0.0f, "", 0.0, "street"},
    // KHR_materials_pbrSpecularGlossiness converted on load (right) beside the metallic-roughness
    // bottle (left): the two should look alike.
    {"ibl_spec_gloss_vs_metal_rough", "SpecGlossVsMetalRough/glTF/SpecGlossVsMetalRough.gltf", {0.0f, 90.0f, 0.0f},
     "studio_small_03_1k.hdr"},
    // KHR_materials_transmission: thin-walled spheres (plain, masked, textured, rough, metallic) in
    // front of a checkered backdrop, seen through the transmission background.
    {"ibl_transmission_test", "TransmissionTest/glTF-Binary/TransmissionTest.glb", {0.0f, 90.0f, 1.1f},
     "studio_small_03_1k.hdr"},
    // KHR_materials_transmission with KHR_materials_volume and KHR_materials_ior: roughness 0 … 1
    // (the background's mips) across, IOR 1 … 2.42 (the blur scales with it; none at IOR 1) down.
    {"ibl_transmission_roughness_test", "TransmissionRoughnessTest/glTF-Binary/TransmissionRoughnessTest.glb",
     {0.0f, 90.0f, 1.3f}, "studio_small_03_1k.hdr"},
    // KHR_materials_iridescence (with transmission and volume on the glass): the globe's carnival
    // glaze and the shade's iridescent lining, seen from a little below.
    {"ibl_iridescence_lamp", "IridescenceLamp/glTF/IridescenceLamp.gltf", {20.0f, 100.0f, 0.9f}, "studio_small_03_1k.hdr"},
    {"interpolation_test_t0_9", "InterpolationTest/glTF-Binary/InterpolationTest.glb", {0.0f, 90.0f, 20.0f}, "", 0.0f, "all", 0.9},
};

class GoldenTest : public GpuTest, public ::testing::WithParamInterface<GoldenCase> {};

void writeDiff(const std::filesystem::path& path, const std::vector<uint8_t>& a, const uint8_t* b) {
    std::vector<uint8_t> diff(a.size());
    for (size_t i = 0; i < a.size(); i += 4) {
        int d = 0;
        for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[i + c]) - int(b[i + c])));
        const uint8_t v = static_cast<uint8_t>(std::min(255, d * 16));
        diff[i] = v, diff[i + 1] = d > kPixelThreshold ? 0 : v, diff[i + 2] = d > kPixelThreshold ? 0 : v, diff[i + 3] = 255;
    }
    assets::writePng(path, kWidth, kHeight, diff);
}

// Pixels of two kWidth × kHeight RGBA8 images that differ by more than kPixelThreshold levels in
// some channel, and the largest channel difference.
std::pair<size_t, int> compare(const uint8_t* a, const uint8_t* b) {
    size_t differing = 0;
    int maxDifference = 0;
    for (size_t i = 0; i < size_t(kWidth) * kHeight * 4; i += 4) {
        int d = 0;
        for (int ch = 0; ch < 4; ++ch) d = std::max(d, std::abs(int(a[i + ch]) - int(b[i + ch])));
        maxDifference = std::max(maxDifference, d);
        differing += d > kPixelThreshold;
    }
    return {differing, maxDifference};
}

// CANDELA_GOLDEN_KEEP=1: write every render, not only failing ones.
bool keepRenders() {
    const char* keep = std::getenv("CANDELA_GOLDEN_KEEP");
    return keep && std::string(keep) == "1";
}

// The case rendered at kWidth × kHeight (RGBA8) once per shading path of `paths`, by one Renderer
// (the scene loaded and the environment's maps computed once), or nullopt when a shared asset it
// needs is absent; `explain` (if given) receives the last frame's --explain lines.
std::optional<std::vector<std::vector<uint8_t>>> renderPaths(vk::Context& context, const GoldenCase& c,
                                                             const std::vector<options::ShadingPath>& paths,
                                                             std::vector<std::string>* explain = nullptr) {
    scene::Scene scene;
    if (*c.model) {
        const std::filesystem::path path = ::candela::test::sharedAssets() / "models" / c.model;
        if (!std::filesystem::exists(path)) return std::nullopt;
        scene = assets::loadGltf(path);
        if (*c.variant) scene::selectVariant(scene, scene::variantIndex(scene, c.variant));
    } else {
        scene = assets::makeSphereGrid();
    }
    std::optional<assets::Environment> environment;
    if (std::string(c.environment) == "sky") {
        environment = assets::makeProceduralSky();
    } else if (*c.environment) {
        const std::filesystem::path path = ::candela::test::sharedAssets() / "environments" / c.environment;
        if (!std::filesystem::exists(path)) return std::nullopt;
        environment = assets::loadEnvironment(path);
    }
    std::vector<std::string> animations;
    if (*c.animation) animations.emplace_back(c.animation);
    pose::ScenePose pose(scene, pose::selectAnimations(scene, animations));
    pose.evaluate(c.time);
    RenderSettings settings{.width = kWidth, .height = kHeight, .scene = &scene, .pose = &pose};
    settings.camera.orbit = c.orbit;
    settings.camera.target = c.target;
    settings.camera.fovYDegrees = c.fovYDegrees;
    settings.drawSelection.lodErrorPixels = c.lodError;
    settings.tonemap.background = shading::srgbDecode(glm::vec3(0x26 / 255.0f));
    if (environment) {
        settings.environment = &*environment;
        settings.defaultLights = false;
        settings.ibl.rotationDegrees = c.environmentRotation;
    }
    // One sample, as lavapipe's default that the goldens were approved at: a GPU's default (4)
    // would move every silhouette pixel, and the GPU check compares the same frame on any device.
    settings.msaa = 1;
    Renderer renderer(context);
    std::vector<std::vector<uint8_t>> out;
    for (const options::ShadingPath path : paths) {
        settings.shadingPath = path;
        out.push_back(renderer.capture(settings).rgba8);
    }
    if (explain) *explain = renderer.explain();
    return out;
}

// The case on `shadingPath` (see renderPaths).
std::optional<std::vector<uint8_t>> render(vk::Context& context, const GoldenCase& c,
                                           options::ShadingPath shadingPath = options::ShadingPath::Auto) {
    auto images = renderPaths(context, c, {shadingPath});
    if (!images) return std::nullopt;
    return std::move(images->front());
}

TEST_P(GoldenTest, MatchesApprovedImage) {
    const GoldenCase& c = GetParam();
    const std::optional<std::vector<uint8_t>> rendered = render(context(), c);
    if (!rendered) GTEST_SKIP() << "shared asset missing for " << c.name;
    const std::vector<uint8_t>& image = *rendered;
    const std::filesystem::path outDir = ::candela::test::goldenOut();
    std::filesystem::create_directories(outDir);
    const std::filesystem::path golden = ::candela::test::goldenDir() / (std::string(c.name) + ".png");
    const std::filesystem::path actual = outDir / (std::string(c.name) + ".actual.png");
    int w = 0, h = 0, channels = 0;
    stbi_uc* expected = stbi_load(golden.c_str(), &w, &h, &channels, 4);
    if (!expected) {
        assets::writePng(actual, kWidth, kHeight, image);
        FAIL() << "no golden " << golden << "; look at " << actual << " and approve it with tools/approve-goldens.sh";
    }
    ASSERT_EQ(w, int(kWidth));
    ASSERT_EQ(h, int(kHeight));
    const auto [differing, maxDifference] = compare(image.data(), expected);
    const double share = double(differing) / (kWidth * kHeight);
    const bool lavapipe = context().caps().driver == VK_DRIVER_ID_MESA_LLVMPIPE;
    const double flip = lavapipe ? 0.0 : flipMean(image.data(), expected);
    const bool pass = lavapipe ? share <= kMaxDifferingShare && maxDifference <= kMaxDifference : flip <= kOtherDriverMaxFlipMean;
    if (!pass || keepRenders()) assets::writePng(actual, kWidth, kHeight, image);
    if (!pass) {
        writeDiff(outDir / (std::string(c.name) + ".diff.png"), image, expected);
    }
    stbi_image_free(expected);
    EXPECT_TRUE(pass) << c.name << ": " << differing << " pixels (" << share * 100.0 << "%) differ by more than "
                      << kPixelThreshold << " levels; max difference " << maxDifference
                      << (lavapipe ? std::string() : "; mean FLIP " + std::to_string(flip) + " (" + context().report().name + ")")
                      << "; see " << outDir;
}

// Two paths, one truth (docs/shading-paths.md): every golden case through the forward path and the
// visibility path (which shades in compute from the same material and lighting code). Metric, per
// RGB channel over the image: the mean difference at most 0.05 levels (of 255) and the 99.9th
// percentile at most 4 levels. Measured over the cases: mean ≤ 0.017 (ibl_damaged_helmet), 99.9th
// percentile ≤ 3 (cesium_milk_truck), 0–1 for most. They differ where the texture level of detail
// does: the forward path's implicit derivatives are a 2×2 quad's, which at silhouettes reach across
// the edge and at grazing angles (the truck's roof) average a fast-changing footprint, while the
// visibility path's are each pixel's own (a few silhouette pixels of DamagedHelmet differ by up to
// 58 levels); and by the sky's rounding (composited under the image in float by the tonemap on the
// visibility path, in the 16-bit image by the skybox pass on the forward one).
constexpr double kPathMeanDifference = 0.05;
constexpr int kPathPercentileDifference = 4;

TEST_P(GoldenTest, ShadingPathsAgree) {
    const GoldenCase& c = GetParam();
    if (!context().choices().visibilityUnsupported.empty()) GTEST_SKIP() << context().choices().visibilityUnsupported;
    std::vector<std::string> explain;
    const auto images = renderPaths(context(), c, {options::ShadingPath::Forward, options::ShadingPath::Visibility}, &explain);
    if (!images) GTEST_SKIP() << "shared asset missing for " << c.name;
    const std::vector<uint8_t>* forward = &(*images)[0];
    const std::vector<uint8_t>* visibility = &(*images)[1];
    EXPECT_TRUE(std::any_of(explain.begin(), explain.end(),
                            [](const std::string& l) { return l.starts_with("shading path: visibility"); }))
        << c.name << ": the frame did not take the visibility path";
    std::vector<int> differences;
    double sum = 0.0;
    for (size_t i = 0; i < forward->size(); i += 4)
        for (int ch = 0; ch < 3; ++ch) {
            const int d = std::abs(int((*forward)[i + ch]) - int((*visibility)[i + ch]));
            differences.push_back(d);
            sum += d;
        }
    const double mean = sum / double(differences.size());
    std::nth_element(differences.begin(), differences.begin() + differences.size() * 999 / 1000, differences.end());
    const int percentile = differences[differences.size() * 999 / 1000];
    RecordProperty("mean", std::to_string(mean));
    RecordProperty("p99.9", percentile);
    EXPECT_LE(mean, kPathMeanDifference) << c.name;
    EXPECT_LE(percentile, kPathPercentileDifference) << c.name << " (mean " << mean << ")";
    const bool failed = HasFailure();
    if (failed || keepRenders()) {
        const std::filesystem::path outDir = ::candela::test::goldenOut();
        std::filesystem::create_directories(outDir);
        assets::writePng(outDir / (std::string(c.name) + ".visibility.png"), kWidth, kHeight, *visibility);
        if (failed) writeDiff(outDir / (std::string(c.name) + ".paths.diff.png"), *visibility, forward->data());
    }
}

// Compressed files against their plain versions. Compression quantizes positions, normals and
// texture coordinates, which moves silhouettes, shading and texture lookups by a fraction of a
// pixel or level; a decoding error (a wrong attribute, filter, order or index) changes much of the
// image. Metric: at most 2% of the pixels differ by more than 3 levels (the golden threshold).
// Both are drawn with one camera, the plain file's: framing fits the vertices, which quantization
// moves too. Its field of view is the framing cone's 30° (the bounding sphere fills the height, as
// model-viewer shows a model), not the one fitted to the silhouette: the share of pixels that
// quantization moves grows with the model's size in the image (the Draco truck: 1.05% at the box
// framing the threshold was set at, 2.40% when fitted to its silhouette, bigger).
constexpr double kCompressedMaxDifferingShare = 0.02;

// `c` with the plain file's framed distance and target given whole, at the framing cone's 30°.
GoldenCase withItsFramedCamera(GoldenCase c) {
    const scene::Scene scene = assets::loadGltf(::candela::test::sharedAssets() / "models" / c.model);
    const scene::OrbitCamera camera = Renderer::orbitCamera(
        scene, {.orbit = glm::vec3(c.orbit.x, c.orbit.y, 0.0f), .fovYDegrees = scene::kFramingConeDegrees}, float(kWidth) / float(kHeight));
    c.orbit.z = camera.radius;
    c.target = camera.target;
    c.fovYDegrees = camera.fovYDegrees;
    return c;
}

// KHR_draco_mesh_compression: the Draco CesiumMilkTruck (measured: 1.55% of the pixels differ, on
// edges, the grille and the textured logo).
TEST_F(GpuTest, DracoRendersLikeThePlainFile) {
    const GoldenCase truck{"cesium_milk_truck", "CesiumMilkTruck/glTF-Binary/CesiumMilkTruck.glb", {30.0f, 75.0f, 0.0f}};
    if (!std::filesystem::exists(::candela::test::sharedAssets() / "models" / truck.model)) GTEST_SKIP() << "../shared/assets not present";
    const GoldenCase plain = withItsFramedCamera(truck);
    GoldenCase draco = plain;
    draco.model = "CesiumMilkTruck/glTF-Draco/CesiumMilkTruck.gltf";
    const auto a = render(context(), plain), b = render(context(), draco);
    if (!a || !b) GTEST_SKIP() << "../shared/assets not present";
    const auto [differing, maxDifference] = compare(a->data(), b->data());
    const double share = double(differing) / (kWidth * kHeight);
    std::printf("%.2f%% of the pixels differ by more than %d levels (max %d)\n", 100.0 * share, kPixelThreshold, maxDifference);
    EXPECT_LE(share, kCompressedMaxDifferingShare) << differing << " pixels differ by more than " << kPixelThreshold << " levels (max "
                           << maxDifference << ")";
}

// EXT_meshopt_compression: DamagedHelmet through gltfpack -cc (measured: 0.46% of the pixels differ,
// max 145 levels on a few edge pixels; 0.23%, max 70, at the box framing, the helmet smaller).
TEST_F(GpuTest, MeshoptRendersLikeThePlainFile) {
    const std::filesystem::path models = ::candela::test::sharedAssets() / "models";
    if (!std::filesystem::exists(models / "DamagedHelmet/glTF-Binary/DamagedHelmet.glb")) GTEST_SKIP() << "../shared/assets not present";
    TempDir dir;
    const std::filesystem::path packed = dir.path() / "helmet.glb";
    assets::test::gltfpack(models / "DamagedHelmet/glTF-Binary/DamagedHelmet.glb", packed);
    ASSERT_FALSE(HasFailure());
    const GoldenCase plain = withItsFramedCamera({"damaged_helmet", "DamagedHelmet/glTF-Binary/DamagedHelmet.glb", {-30.0f, 80.0f, 0.0f}});
    const std::string packedPath = packed.string();
    GoldenCase meshopt = plain;
    meshopt.model = packedPath.c_str();  // absolute: replaces the models folder
    const auto a = render(context(), plain), b = render(context(), meshopt);
    ASSERT_TRUE(a && b);
    const auto [differing, maxDifference] = compare(a->data(), b->data());
    const double share = double(differing) / (kWidth * kHeight);
    std::printf("%.2f%% of the pixels differ by more than %d levels (max %d)\n", 100.0 * share, kPixelThreshold, maxDifference);
    EXPECT_LE(share, kCompressedMaxDifferingShare) << differing << " pixels differ by more than " << kPixelThreshold
                                                   << " levels (max " << maxDifference << ")";
}

INSTANTIATE_TEST_SUITE_P(Models, GoldenTest, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<GoldenCase>& row) { return std::string(row.param.name); });

}  // namespace
}  // namespace candela::test::golden_test
