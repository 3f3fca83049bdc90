// KHR_materials_diffuse_transmission and KHR_materials_dispersion rendered: the diffuse
// transmission keeps the white furnace (and never exceeds it through an absorbing volume), both
// layers stay finite at their extremes, dispersion 0 draws the image without it, the debug view
// `dispersion` shows the angle Snell's law gives between the red and blue rays, and the visibility
// path's compute shading draws both as the forward pass does.
#include "gpu_test.h"
#include "shading_summary_util.h"
#include "sphere_furnace.h"

#include "../unit/brdf_reference.h"
#include "assets/builtin_scenes.h"
#include "render/renderer.h"
#include "shared/tonemap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace candela::test {
namespace {

// White furnace of the diffuse transmission: the furnace spheres (white, roughness 0 … 1 across,
// dielectric bottom row and metal top row) with diffuse transmission 0, 0.25, 0.5, 0.75, 1 across
// (the layer on at 0 too) and a white colour, in a uniform environment of radiance 1, no lights:
// the irradiance from behind equals the irradiance in front, so the material returns what it
// returns opaque. Thin-walled and with a volume of thickness 0.5 that absorbs nothing. Metric and
// tolerances of the furnace (sphere_furnace.h): max |x − 1| ≤ 0.02, never above 1 + 1/1024. Then
// through an absorbing volume (attenuation colour (0.5, 0.8, 1) at distance 0.5): never above 1,
// and the dielectric's red below its blue where the layer transmits.
TEST_F(GpuTest, DiffuseTransmissionKeepsTheWhiteFurnace) {
    const assets::Environment env = constantEnvironment(64, 32, glm::vec3(1.0f));
    const std::vector<Sphere> spheres = furnaceSpheres();
    Renderer renderer(context());
    for (int pass = 0; pass < 3; ++pass) {
        scene::Scene scene = sphereScene(spheres, 64, 32);
        for (size_t i = 0; i < spheres.size(); ++i) {
            scene::Material& m = scene.materials[i];
            m.diffuseTransmissionFactor = kRoughness[i % kRoughness.size()];
            m.animatedLayers = scene::kLayerDiffuseTransmission;  // factor 0 too
            m.thicknessFactor = pass == 0 ? 0.0f : 0.5f;
            if (pass == 2) {
                m.attenuationColor = glm::vec3(0.5f, 0.8f, 1.0f);
                m.attenuationDistance = 0.5f;
            }
        }
        const std::string key = pass == 0 ? "diffuseTransmission" : pass == 1 ? "diffuseTransmissionVolume" : "diffuseTransmissionAbsorbing";
        SCOPED_TRACE(key);
        const RenderSettings settings = furnaceSettings(scene, env);
        renderer.sceneReplaced();  // each pass's scene is a new one at the same address
        const CapturedFrame frame = renderer.capture(settings);
        ASSERT_EQ(frameProblem(frame), "");
        EXPECT_TRUE(pass == 0 ? paysFor(renderer, scene::kLayerDiffuseTransmission, /*exactly=*/true)
                              : paysFor(renderer, scene::kLayerVolume | scene::kLayerDiffuseTransmission));
        EXPECT_TRUE(renderer.lastPlan()->leavesOut(PlannedPart::TransmissionBackground));  // no background needed
        const std::vector<FurnacePixel> pixels = furnacePixels(frame, scene, settings, spheres);
        if (pass < 2) {
            expectWhiteFurnace(pixels, spheres.size(), key);
            continue;
        }
        double highest = -1.0;
        for (const FurnacePixel& fp : pixels)
            for (int c = 0; c < 3; ++c) highest = std::max(highest, double(fp.value[c]) - 1.0);
        measured(key + "MaxAboveOne", highest);
        EXPECT_LE(highest, 1.0 / 1024.0);
        const std::vector<ChannelRange> range = channelRange(pixels, spheres.size());
        EXPECT_LT(range[4].highest.r, range[4].lowest.b) << "dt 1 through the absorbing volume: red absorbed";
        EXPECT_GE(range[0].lowest.r, 1.0f - 0.02f) << "dt 0: the volume is not in the way";
    }
}

// The stiff cases of the diffuse transmission in one frame lit by the environment, a point
// light behind the spheres (1e5) and one in front: weight 0 (the layer on) and 1; thickness 0, 1 and
// 1e6; attenuation distance 1e-6 and infinity; a black colour; transmission 1 over it (which
// overrides it); a coat over it. Metric: every value of the float frame finite and non-negative,
// alpha in [0, 1] (frameProblem), the debug view `diffuse-transmission` too; in that view a weight 0,
// a black colour and a transmission of 1 let nothing through, a thin weight 1 lets light through,
// and 1e6 of a medium of attenuation distance 1e-6 and colour (0.5, 0.8, 1) only the blue.
TEST_F(GpuTest, DiffuseTransmissionExtremesStayFinite) {
    const assets::Environment env = constantEnvironment(64, 32, glm::vec3(0.5f, 0.7f, 1.0f));
    const std::vector<Sphere> spheres = furnaceSpheres();
    scene::Scene scene = sphereScene(spheres, 64, 32);
    struct Case {
        float weight;
        glm::vec3 color;
        float thickness, attenuationDistance, transmission, clearcoat;
    };
    const Case cases[] = {{0.0f, glm::vec3(1.0f), 0.0f, 0.0f, 0.0f, 0.0f},          // 0: weight 0
                          {1.0f, glm::vec3(1.0f, 0.5f, 0.2f), 0.0f, 0.0f, 0.0f, 0.0f},  // 1: thin, weight 1
                          {1.0f, glm::vec3(1.0f), 1e6f, 1e-6f, 0.0f, 0.0f},         // 2: all absorbed but blue
                          {1.0f, glm::vec3(0.0f), 1.0f, 0.0f, 0.0f, 0.0f},          // 3: black
                          {1.0f, glm::vec3(1.0f), 0.0f, 0.0f, 1.0f, 0.0f},          // 4: transmission overrides
                          {0.5f, glm::vec3(1.0f), 1.0f, 1e-6f, 0.0f, 1.0f},         // 5: coated, absorbed
                          {1.0f, glm::vec3(1.0f), 1e6f, 0.0f, 0.0f, 0.0f},          // 6: thick, no absorption
                          {0.5f, glm::vec3(1.0f), 1.0f, 1.0f, 0.5f, 0.0f},          // 7: half of each
                          {1.0f, glm::vec3(1.0f), 0.0f, 0.0f, 0.0f, 1.0f},          // 8: coated
                          {1.0f, glm::vec3(1.0f), 1.0f, 1.0f, 0.0f, 0.0f}};         // 9: a volume
    for (size_t i = 0; i < spheres.size(); ++i) {
        scene::Material& m = scene.materials[i];
        const Case& c = cases[i];
        m.metallicFactor = 0.0f;
        m.diffuseTransmissionFactor = c.weight;
        m.diffuseTransmissionColorFactor = c.color;
        m.animatedLayers = scene::kLayerDiffuseTransmission;
        m.thicknessFactor = c.thickness;
        m.attenuationDistance = c.attenuationDistance;
        m.attenuationColor = glm::vec3(0.5f, 0.8f, 1.0f);
        m.transmissionFactor = c.transmission;
        m.clearcoatFactor = c.clearcoat;
    }
    scene::Light behind, front;
    behind.position = glm::vec3(0.0f, 0.0f, -6.0f);
    behind.intensity = 1e5f;
    front.position = glm::vec3(2.0f, 3.0f, 8.0f);
    front.intensity = 50.0f;
    scene.lights = {behind, front};
    Renderer renderer(context());
    RenderSettings settings = furnaceSettings(scene, env);
    settings.ibl.skybox = true;
    EXPECT_EQ(frameProblem(renderer.capture(settings)), "");
    EXPECT_TRUE(paysFor(renderer, scene::kLayerDiffuseTransmission));
    settings.debugView = options::DebugView::DiffuseTransmission;
    const CapturedFrame light = renderer.capture(settings);
    EXPECT_EQ(frameProblem(light), "");
    scene::Scene opaque = scene;
    for (scene::Material& m : opaque.materials) m.transmissionFactor = 0.0f;
    const CapturedFrame coverage = renderer.capture(furnaceSettings(opaque, env));
    const std::vector<ChannelRange> range = channelRange(furnacePixels(light, scene, settings, spheres, &coverage), spheres.size());
    for (size_t i : {0u, 3u, 4u}) EXPECT_EQ(maxComponent(range[i].highest), 0.0f) << "sphere " << i;
    EXPECT_GT(minComponent(range[1].lowest), 0.0f);
    EXPECT_EQ(range[2].highest.r, 0.0f);
    EXPECT_EQ(range[2].highest.g, 0.0f);
    EXPECT_GT(range[2].lowest.b, 0.0f);
    EXPECT_GT(minComponent(range[6].lowest), 0.0f);
}

// Weight 0 is no diffuse transmission: the sphere grid (metallic 0 or 1, where the core's and the
// specification's diffuse weights agree) drawn with the layer on at weight 0 draws the core image.
// Metric: max absolute difference per 8-bit channel ≤ 1 level (as
// LayeredProgramAtTheCoreValuesDrawsTheCoreImage: the two programs round the same formulas apart).
TEST_F(GpuTest, DiffuseTransmissionOfWeightZeroDrawsTheCoreImage) {
    scene::Scene core = assets::makeSphereGrid();
    for (scene::Material& m : core.materials) m.metallicFactor = m.metallicFactor < 0.5f ? 0.0f : 1.0f;
    scene::Scene layered = core;
    for (scene::Material& m : layered.materials) m.animatedLayers = scene::kLayerDiffuseTransmission;
    Renderer renderer(context());
    const CapturedFrame a = renderer.capture({.width = 240, .height = 135, .scene = &core});
    const CapturedFrame b = renderer.capture({.width = 240, .height = 135, .scene = &layered});
    EXPECT_TRUE(paysFor(renderer, scene::kLayerDiffuseTransmission));
    ASSERT_EQ(a.rgba8.size(), b.rgba8.size());
    int worst = 0;
    for (size_t i = 0; i < a.rgba8.size(); ++i) worst = std::max(worst, std::abs(int(a.rgba8[i]) - int(b.rgba8[i])));
    measured("diffuseTransmissionZeroMaxLevels", worst);
    EXPECT_LE(worst, 1);
}

// An equirectangular environment of vertical stripes (white and black, 8 texels wide, 1 above the
// horizon's blue): what a clear sphere shows through its volume moves with the IOR, so the colour
// channels of a dispersive one come apart at the stripes' edges.
assets::Environment stripedEnvironment() {
    assets::Environment env = constantEnvironment(256, 128, glm::vec3(0.0f));
    for (uint32_t y = 0; y < env.height; ++y)
        for (uint32_t x = 0; x < env.width; ++x) {
            const float v = (x / 8) % 2 == 0 ? 1.0f : 0.05f;
            float* texel = &env.rgb[(size_t(y) * env.width + x) * 3];
            texel[0] = texel[1] = texel[2] = v;
        }
    return env;
}

// Clear spheres (transmission 1, roughness 0, IOR 1.5, a volume of thickness 1) over the striped
// sky: dispersion 0 with the layer on draws the image without the layer; dispersion 10 leaves the
// green channel as it was (the green ray is the material's) and moves red and blue; dispersion 100
// and 1e6 (the red IOR clamped to 1, the blue's 2.75 and 12501.5) stay finite. Metric: the float
// frames' values, compared per channel over every pixel: dispersion 0 exactly the same, the green
// of dispersion 10 within 1e-6 (measured: the same), its red and blue more than 0.05 apart somewhere
// (measured 0.10: the exit points of red and blue are about 0.09 m apart, 2 px, across stripe edges
// the small IBL cube of the furnace settings softens over several pixels).
TEST_F(GpuTest, DispersionZeroDrawsTheImageWithoutItAndLargeStaysFinite) {
    const assets::Environment env = stripedEnvironment();
    const std::vector<Sphere> spheres = furnaceSpheres();
    const auto glass = [&](float dispersion, bool layer) {
        scene::Scene scene = sphereScene(spheres, 64, 32);
        for (scene::Material& m : scene.materials) {
            m.metallicFactor = 0.0f;
            m.roughnessFactor = 0.0f;
            m.transmissionFactor = 1.0f;
            m.thicknessFactor = 1.0f;
            m.dispersion = dispersion;
            if (layer) m.animatedLayers = scene::kLayerDispersion;
        }
        return scene;
    };
    Renderer renderer(context());
    const auto render = [&](const scene::Scene& scene) {
        RenderSettings settings = furnaceSettings(scene, env);
        settings.ibl.skybox = true;
        renderer.sceneReplaced();
        return renderer.capture(settings);
    };
    const scene::Scene plainScene = glass(0.0f, false), zeroScene = glass(0.0f, true), tenScene = glass(10.0f, false);
    const CapturedFrame plain = render(plainScene);
    EXPECT_TRUE(paysFor(renderer, scene::kLayerTransmission | scene::kLayerVolume, /*exactly=*/true));
    const CapturedFrame zero = render(zeroScene);
    EXPECT_TRUE(paysFor(renderer, scene::kLayerTransmission | scene::kLayerVolume | scene::kLayerDispersion));
    const CapturedFrame ten = render(tenScene);
    ASSERT_EQ(frameProblem(plain), "");
    ASSERT_EQ(plain.rgba32f.size(), zero.rgba32f.size());
    double zeroDifference = 0.0, greenDifference = 0.0, redBlueDifference = 0.0;
    for (size_t i = 0; i < plain.rgba32f.size(); ++i) {
        zeroDifference = std::max(zeroDifference, double(std::abs(plain.rgba32f[i] - zero.rgba32f[i])));
        const double d = std::abs(plain.rgba32f[i] - ten.rgba32f[i]);
        if (i % 4 == 1) greenDifference = std::max(greenDifference, d);
        if (i % 4 == 0 || i % 4 == 2) redBlueDifference = std::max(redBlueDifference, d);
    }
    measured("dispersionZeroMaxDifference", zeroDifference);
    measured("dispersionTenGreenMaxDifference", greenDifference);
    measured("dispersionTenRedBlueMaxDifference", redBlueDifference);
    EXPECT_EQ(zeroDifference, 0.0);
    EXPECT_LE(greenDifference, 1e-6);
    EXPECT_GT(redBlueDifference, 0.05) << "the stripes' red and blue come apart";  // measured 0.10
    for (float dispersion : {100.0f, 1e6f}) {
        const scene::Scene large = glass(dispersion, false);
        EXPECT_EQ(frameProblem(render(large)), "") << "dispersion " << dispersion;
    }
}

// The debug view `dispersion` (the angle between the red and the blue refracted rays, in degrees,
// 1° white) over the furnace spheres made clear with dispersion 1 (IORs 1.4875, 1.5, 1.5125) against
// Snell's law in double at each interior pixel's N·V (ray cast to the analytic sphere):
// asin(sin θ / n_C) − asin(sin θ / n_F). Metric: |view − expected| in degrees over interior pixels.
// Tolerance 0.02°: the mesh's interpolated normals (a 64 × 32 UV sphere) and the view's 8-bit
// output, which the float frame's RGBA16F matches.
TEST_F(GpuTest, DispersionViewShowsTheAngleBetweenTheRedAndBlueRays) {
    const assets::Environment env = constantEnvironment(64, 32, glm::vec3(1.0f));
    const std::vector<Sphere> spheres = furnaceSpheres();
    scene::Scene scene = sphereScene(spheres, 64, 32);
    for (scene::Material& m : scene.materials) {
        m.metallicFactor = 0.0f;
        m.transmissionFactor = 1.0f;
        m.thicknessFactor = 1.0f;
        m.dispersion = 1.0f;
    }
    Renderer renderer(context());
    RenderSettings settings = furnaceSettings(scene, env);
    settings.debugView = options::DebugView::Dispersion;
    const CapturedFrame frame = renderer.capture(settings);
    ASSERT_EQ(frameProblem(frame), "");
    const scene::ViewSetup view = Renderer::resolveView(scene, settings.camera, float(frame.width) / float(frame.height));
    const glm::dvec3 iors = reference::dispersionIors(1.5, 1.0);
    double worst = 0.0, largest = 0.0;
    size_t count = 0;
    for (const FurnacePixel& fp : furnacePixels(frame, scene, settings, spheres)) {
        const Hit hit = castRay(view, frame.width, frame.height, fp.x, fp.y, spheres);
        if (hit.sphere < 0) continue;
        const double sine = std::sqrt(std::max(1.0 - hit.mu * hit.mu, 0.0));
        const double expected = (std::asin(sine / iors.x) - std::asin(sine / iors.z)) * 180.0 / reference::kPi;
        const double got = shading::srgbEncode(glm::vec3(fp.value)).r;  // data views are sRGB-decoded for display
        worst = std::max(worst, std::abs(got - expected));
        largest = std::max(largest, expected);
        ++count;
    }
    measured("dispersionViewMaxError", worst);
    measured("dispersionViewLargestAngle", largest);
    EXPECT_GT(count, 10000u);
    EXPECT_GT(largest, 0.3) << "the grazing pixels show a spread";
    EXPECT_LE(worst, 0.02);
}

// Both layers through the visibility path's compute shading (which runs the forward pass's
// material code, shading/shade.glsl): the top row diffusely transmitting (weight 0.25 … 1, a volume
// on two), the bottom row dispersive glass (dispersion 0.33 … 10), lit from behind and by the
// environment. Metric: RGB difference of the 8-bit frames in levels; tolerance as the debug views'
// comparison of the paths (ShadingPathTest.DebugViewsAgreeOnBothPaths): mean ≤ 0.05, every channel
// within 2 levels.
TEST_F(GpuTest, DiffuseTransmissionAndDispersionAgreeOnBothShadingPaths) {
    if (!context().choices().visibilityUnsupported.empty()) GTEST_SKIP() << context().choices().visibilityUnsupported;
    const assets::Environment env = stripedEnvironment();
    const std::vector<Sphere> spheres = furnaceSpheres();
    scene::Scene scene = sphereScene(spheres, 64, 32);
    for (size_t i = 0; i < spheres.size(); ++i) {
        scene::Material& m = scene.materials[i];
        const float step = float(i % 5);
        m.metallicFactor = 0.0f;
        m.roughnessFactor = 0.3f;
        m.baseColorFactor = glm::vec4(0.3f, 0.7f, 0.2f, 1.0f);
        if (i >= 5) {
            m.diffuseTransmissionFactor = 0.25f + 0.1875f * step;
            m.diffuseTransmissionColorFactor = glm::vec3(1.0f, 0.4f, 0.1f);
            m.thicknessFactor = step >= 3.0f ? 0.5f : 0.0f;
            m.attenuationColor = glm::vec3(0.8f, 0.5f, 0.3f);
            m.attenuationDistance = 1.0f;
        } else {
            m.baseColorFactor = glm::vec4(1.0f);
            m.roughnessFactor = 0.0f;
            m.transmissionFactor = 1.0f;
            m.thicknessFactor = 1.0f;
            m.dispersion = std::array<float, 5>{0.33f, 1.0f, 2.04f, 5.0f, 10.0f}[i];
        }
    }
    scene::Light behind;
    behind.position = glm::vec3(0.0f, 0.0f, -6.0f);
    behind.intensity = 200.0f;
    scene.lights = {behind};
    Renderer renderer(context());
    RenderSettings settings{.width = 320, .height = 180, .scene = &scene, .camera = furnaceCamera(), .defaultLights = false,
                            .environment = &env, .iblQuality = smallQuality()};
    settings.shadingPath = options::ShadingPath::Forward;
    const CapturedFrame forward = renderer.capture(settings);
    settings.shadingPath = options::ShadingPath::Visibility;
    const CapturedFrame visibility = renderer.capture(settings);
    ASSERT_NE(renderer.lastPlan(), nullptr);
    EXPECT_EQ(renderer.lastPlan()->path, options::ShadingPath::Visibility);
    ASSERT_EQ(forward.rgba8.size(), visibility.rgba8.size());
    double sum = 0.0;
    int largest = 0;
    for (size_t i = 0; i < forward.rgba8.size(); i += 4)
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(forward.rgba8[i + c]) - int(visibility.rgba8[i + c]));
            sum += d;
            largest = std::max(largest, d);
        }
    const double mean = sum / double(forward.rgba8.size() / 4 * 3);
    measured("shadingPathsMeanDifference", mean);
    measured("shadingPathsLargestDifference", largest);
    EXPECT_LE(mean, 0.05);
    EXPECT_LE(largest, 2);
}

}  // namespace
}  // namespace candela::test
