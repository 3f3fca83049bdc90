// What the frame graph leaves out, asserted from the compiled graph and from the maps' record of
// the frame (ibl_maps::IblFrame), never from timings or the --explain words: no environment → no
// precompute, no skybox, no IBL shading; an unchanged environment → no precompute; changing only
// how maps are read (rotation, intensity) → no precompute; changing the quality → precompute
// without the LUT when the LUT's settings did not change; the on-disk cache replaces the
// precompute of a later run and a corrupt cache file is recomputed.

#include "gpu_test.h"
#include "shading_summary_util.h"

#include "assets/builtin_scenes.h"
#include "assets/procedural_sky.h"
#include "ibl/ibl_cache_file.h"
#include "render/renderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace candela::test {
namespace {

// Names of the passes that ran (declared and not culled) in the renderer's last graph.
std::vector<std::string> ranPasses(const Renderer& renderer) {
    std::vector<std::string> names;
    const graph::RenderGraph& graph = renderer.lastGraph();
    for (uint32_t p = 0; p < graph.declaration().passes.size(); ++p)
        if (graph.compiled().passes[p].cullReason == graph::CullReason::None)
            names.push_back(graph.declaration().passes[p].name);
    return names;
}

bool has(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

bool anyIbl(const std::vector<std::string>& names) {
    return std::any_of(names.begin(), names.end(), [](const std::string& n) { return n.rfind("ibl_", 0) == 0; });
}

bool explains(const Renderer& renderer, const std::string& fragment) {
    const std::vector<std::string> lines = renderer.explain();
    return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(fragment) != std::string::npos; });
}

class IblGraphTest : public GpuTest {
protected:
    RenderSettings settings(const assets::Environment* environment) {
        RenderSettings s{.width = 48, .height = 32, .scene = &mScene};
        s.msaa = 1;  // the variant names below are the single-sample ones, on any device
        s.environment = environment;
        s.iblQuality.cubeSize = 32;  // small maps: these tests are about the graph
        s.iblQuality.shSourceSize = 8;
        s.iblQuality.lutSize = 16;
        s.iblQuality.lutSamples = 16;
        s.iblQuality.prefilterSamples = 8;
        return s;
    }
    scene::Scene mScene = assets::makeSphereGrid();
    assets::Environment mSky = assets::makeProceduralSky({.width = 64, .height = 32});
};

TEST_F(IblGraphTest, NoEnvironmentRunsNoPrecomputeNoSkyboxNoIblShading) {
    Renderer renderer(context());
    renderer.capture(settings(nullptr));
    const std::vector<std::string> passes = ranPasses(renderer);
    EXPECT_FALSE(anyIbl(passes));
    EXPECT_FALSE(has(passes, "skybox"));
    EXPECT_FALSE(renderer.lastGraph().findPass("skybox").has_value()) << "not even declared";
    EXPECT_EQ(renderer.iblMaps().lastFrame().maps, ibl_maps::IblFrame::Maps::None);
    EXPECT_TRUE(explains(renderer, "left out: image-based lighting (no environment)"));
    EXPECT_EQ(variantDraws(renderer, "pbr"), 49u) << "the forward variant without IBL work";
}

TEST_F(IblGraphTest, PrecomputeRunsOnceThenOnlyWhenEnvironmentOrQualityChanges) {
    Renderer renderer(context());
    RenderSettings s = settings(&mSky);
    renderer.capture(s);
    std::vector<std::string> passes = ranPasses(renderer);
    for (const char* name : {"ibl_brdf_lut", "ibl_cubemap", "ibl_prefilter", "ibl_irradiance_cube", "forward", "tonemap"})
        EXPECT_TRUE(has(passes, name)) << name;
    EXPECT_FALSE(has(passes, "ibl_irradiance_sh"));
    EXPECT_EQ(renderer.lastPlan()->sky, SkyPlacement::Tonemap);
    const ibl_maps::IblFrame first = renderer.iblMaps().lastFrame();
    EXPECT_EQ(first.maps, ibl_maps::IblFrame::Maps::Computed);
    EXPECT_TRUE(first.lutComputed);
    EXPECT_EQ(first.irradiance, ibl::IrradianceMode::Cube);
    EXPECT_FALSE(first.sheen) << "no material has a sheen";
    EXPECT_TRUE(explains(renderer, "ibl: maps computed by this frame's precompute passes"));
    EXPECT_EQ(variantDraws(renderer, "pbr+ibl-cube"), 49u);

    // Same environment: the maps are imported, no precompute pass is even declared.
    renderer.capture(s);
    passes = ranPasses(renderer);
    EXPECT_FALSE(anyIbl(passes));
    for (const graph::PassDecl& pass : renderer.lastGraph().declaration().passes)
        EXPECT_NE(pass.name.rfind("ibl_", 0), 0u) << pass.name;
    EXPECT_EQ(renderer.iblMaps().lastFrame().maps, ibl_maps::IblFrame::Maps::Kept);
    EXPECT_FALSE(renderer.iblMaps().lastFrame().lutComputed);

    // Reading the maps differently changes no map.
    s.ibl.rotationDegrees = 40.0f;
    s.ibl.intensity = 2.0f;
    s.ibl.skyboxBlur = 0.5f;
    renderer.capture(s);
    EXPECT_FALSE(anyIbl(ranPasses(renderer)));

    // Another prefilter setting: precompute again, but the LUT's settings did not change.
    s.iblQuality.prefilterSamples = 16;
    renderer.capture(s);
    passes = ranPasses(renderer);
    EXPECT_TRUE(has(passes, "ibl_prefilter"));
    EXPECT_FALSE(has(passes, "ibl_brdf_lut"));
    EXPECT_EQ(renderer.iblMaps().lastFrame().maps, ibl_maps::IblFrame::Maps::Computed);
    EXPECT_FALSE(renderer.iblMaps().lastFrame().lutComputed);

    // Another environment (new content): precompute, still no LUT.
    assets::Environment other = assets::makeProceduralSky({.width = 64, .height = 32, .sunAzimuthDegrees = 120.0f});
    s.environment = &other;
    renderer.capture(s);
    passes = ranPasses(renderer);
    EXPECT_TRUE(has(passes, "ibl_cubemap"));
    EXPECT_FALSE(has(passes, "ibl_brdf_lut"));

    // Irradiance as SH9: its projection replaces the irradiance cube's pass.
    s.iblQuality.irradiance = ibl::IrradianceMode::Sh9;
    renderer.capture(s);
    passes = ranPasses(renderer);
    EXPECT_TRUE(has(passes, "ibl_irradiance_sh"));
    EXPECT_FALSE(has(passes, "ibl_irradiance_cube"));
    EXPECT_EQ(renderer.iblMaps().lastFrame().irradiance, ibl::IrradianceMode::Sh9);
    EXPECT_EQ(variantDraws(renderer, "pbr+ibl-sh9"), 49u);

    // Environment off again: nothing of IBL remains.
    s.environment = nullptr;
    renderer.capture(s);
    EXPECT_FALSE(anyIbl(ranPasses(renderer)));
    EXPECT_FALSE(has(ranPasses(renderer), "skybox"));
}

TEST_F(IblGraphTest, SkyboxToggleLeavesOutOnlyTheSkybox) {
    Renderer renderer(context());
    RenderSettings s = settings(&mSky);
    s.ibl.skybox = false;
    renderer.capture(s);
    EXPECT_FALSE(renderer.lastGraph().findPass("skybox").has_value());
    EXPECT_TRUE(has(ranPasses(renderer), "ibl_prefilter"));
    EXPECT_EQ(renderer.lastPlan()->sky, SkyPlacement::None);
    EXPECT_TRUE(renderer.lastPlan()->leavesOut(PlannedPart::Skybox));
}

TEST_F(IblGraphTest, TheSkyReadsTheImageUnderItOnlyWhereADrawCanHaveWrittenIt) {
    // The grid from the default camera: where the depth is still the far plane's, the image holds
    // its clear value, and the sky's draw does not read it.
    Renderer renderer(context());
    RenderSettings s = settings(&mSky);
    renderer.capture(s);
    ASSERT_TRUE(renderer.lastPlan());
    EXPECT_TRUE(renderer.lastPlan()->skyWhereUncovered);
    EXPECT_TRUE(renderer.lastPlan()->skyOverClearImage);
    // Through a glTF camera with a far plane, geometry on it keeps the cleared depth 0.
    scene::Scene framed = mScene;
    scene::Camera camera;
    camera.zfar = 100.0f;
    camera.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 12.0f));
    framed.cameras.push_back(camera);
    RenderSettings finite = settings(&mSky);
    finite.scene = &framed;
    finite.camera.gltfCamera = 0;
    renderer.capture(finite);
    EXPECT_TRUE(renderer.lastPlan()->skyWhereUncovered);
    EXPECT_FALSE(renderer.lastPlan()->skyOverClearImage);
    // A blended draw leaves the depth as it was, not the image.
    scene::Scene blended = mScene;
    blended.materials[0].alphaMode = scene::AlphaMode::Blend;
    RenderSettings withBlend = settings(&mSky);
    withBlend.scene = &blended;
    renderer.capture(withBlend);
    EXPECT_TRUE(renderer.lastPlan()->skyWhereUncovered);
    EXPECT_FALSE(renderer.lastPlan()->skyOverClearImage);
}

TEST_F(IblGraphTest, CacheReplacesThePrecomputeOfALaterRunAndACorruptFileIsRecomputed) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("candela_ibl_cache_test_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    RenderSettings s = settings(&mSky);
    s.iblCacheDir = dir;
    std::vector<uint8_t> computed;
    {
        Renderer renderer(context());
        computed = renderer.capture(s).rgba8;
        EXPECT_TRUE(has(ranPasses(renderer), "ibl_prefilter"));
        ASSERT_FALSE(renderer.iblMaps().cacheFile().empty());
        EXPECT_TRUE(std::filesystem::exists(renderer.iblMaps().cacheFile()));
    }
    std::filesystem::path file;
    {
        Renderer renderer(context());
        const std::vector<uint8_t> cached = renderer.capture(s).rgba8;
        EXPECT_FALSE(anyIbl(ranPasses(renderer))) << "maps loaded from the cache";
        EXPECT_EQ(renderer.iblMaps().lastFrame().maps, ibl_maps::IblFrame::Maps::FromCache);
        EXPECT_EQ(renderer.iblMaps().source(), ibl_maps::MapsSource::Cache);
        EXPECT_TRUE(cached == computed) << "the cached maps render exactly like the computed ones";
        file = renderer.iblMaps().cacheFile();
    }
    {
        // Flip one byte in the middle: the checksum fails, the maps are recomputed and rewritten.
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(static_cast<std::streamoff>(std::filesystem::file_size(file) / 2));
        f.put('\x5a');
    }
    {
        Renderer renderer(context());
        const std::vector<uint8_t> recomputed = renderer.capture(s).rgba8;
        EXPECT_TRUE(has(ranPasses(renderer), "ibl_prefilter"));
        EXPECT_EQ(renderer.iblMaps().lastFrame().maps, ibl_maps::IblFrame::Maps::Computed);
        EXPECT_TRUE(explains(renderer, "ibl cache: ")) << "why the file was not used";
        EXPECT_TRUE(recomputed == computed);
        std::string reason;
        EXPECT_TRUE(ibl::readCacheFile(file, ibl_maps::iblCacheKey(assets::contentHash(mSky), s.iblQuality), &reason).has_value())
            << reason;
    }
    std::filesystem::remove_all(dir);
}

TEST_F(IblGraphTest, MapsPreparedBeforeTheSceneServeItsUploadAndASheenAsksAgain) {
    // Renderer::prepareEnvironment before any scene (a render command does it while the file
    // loads): the upload that follows keeps those maps, and the frame draws what a renderer that
    // prepared nothing ahead draws; a scene with a sheen gets the maps with the sheen's cube.
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("candela_ibl_prepare_test_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    scene::Scene sheen = assets::makeSphereGrid();
    for (scene::Material& material : sheen.materials) material.sheenColorFactor = glm::vec3(0.8f, 0.5f, 0.3f);
    for (const scene::Scene* drawn : {&mScene, &sheen}) {
        SCOPED_TRACE(drawn == &sheen ? "with a sheen" : "without a sheen");
        RenderSettings s = settings(&mSky);
        s.scene = drawn;
        s.iblCacheDir = dir;
        std::vector<uint8_t> reference;
        {
            Renderer renderer(context());
            reference = renderer.capture(s).rgba8;  // computes the maps and fills the cache
        }
        Renderer renderer(context());
        renderer.prepareEnvironment(&mSky, s.iblQuality, dir);
        EXPECT_EQ(renderer.iblMaps().source(), ibl_maps::MapsSource::Cache) << "read before the scene";
        EXPECT_EQ(renderer.capture(s).rgba8, reference);
        // No map computed: the environment's from the cache (the sheen's LUT is the renderer's own, made once).
        for (const std::string& pass : ranPasses(renderer))
            EXPECT_TRUE(pass.rfind("ibl_", 0) != 0 || pass == "ibl_sheen_lut") << pass;
        EXPECT_EQ(renderer.iblMaps().lastFrame().maps, ibl_maps::IblFrame::Maps::FromCache);
        EXPECT_EQ(renderer.iblMaps().lastFrame().sheen, drawn == &sheen);
    }
    std::filesystem::remove_all(dir);
}

TEST_F(IblGraphTest, MapsReplacedBetweenFramesAreTheOnesBound) {
    // The forward and skybox passes resolve the maps through the graph each frame, so replacing
    // the environment and the maps' size between frames must give exactly the image of a renderer
    // that only ever saw the new ones — in the frame that computes them and in the next.
    const assets::Environment dusk = assets::makeProceduralSky(
        {.width = 64, .height = 32, .sunElevationDegrees = 4.0f, .sunAzimuthDegrees = 200.0f,
         .zenithRadiance = {0.1f, 0.1f, 0.3f}});
    RenderSettings first = settings(&mSky);
    RenderSettings second = settings(&dusk);
    second.iblQuality.cubeSize = 16;  // new images, not only new contents
    Renderer switched(context());
    const CapturedFrame before = switched.capture(first);
    const CapturedFrame afterSwitch = switched.capture(second);
    const CapturedFrame nextFrame = switched.capture(second);
    Renderer fresh(context());
    const CapturedFrame expected = fresh.capture(second);
    EXPECT_NE(before.rgba8, expected.rgba8) << "the two environments must look different for this test to mean anything";
    EXPECT_EQ(afterSwitch.rgba8, expected.rgba8);
    EXPECT_EQ(nextFrame.rgba8, expected.rgba8);
}

}  // namespace
}  // namespace candela::test
