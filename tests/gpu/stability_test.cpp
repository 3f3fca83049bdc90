// Numerical stability of the scene frame graph (forward → tonemap → readback) at the extremes of
// issue 3 item 7, on lavapipe with validation on. Every render is 96×64.
//
// What "stable" means here, checked on every render by renderAndCheck():
//   - HDR (floatOutput, RGBA16F): every value finite; RGB in [0, 60000] (the forward pass clamps
//     radiance to 60000 to stay inside half-float range); coverage alpha in [0, 1].
//   - 8-bit, once per tone mapping operator: every pixel equals the CPU evaluation of
//     shaders/shared/tonemap.h (the code the tonemap pass runs) on that pass's input, the HDR pixel,
//     within kLdrTolerance levels. A NaN turned into black or white by the tonemap cannot hide there.
//   - both for every shading model (pbr, pbr-schlick-ggx, blinn-phong).
// Comparisons between two renders of the same view state their metric and tolerance where made.
#include "gpu_test.h"

#include "assets/builtin_scenes.h"
#include "assets/image_file.h"
#include "render/renderer.h"
#include "shared/tonemap.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <list>
#include <sstream>
#include <string>

namespace candela::test::stability_test {
namespace {

using options::ShadingModel;
using options::Tonemap;

constexpr uint32_t kWidth = 96, kHeight = 64;
constexpr ShadingModel kShadingModels[] = {ShadingModel::Pbr, ShadingModel::PbrSchlickGgx,
                                           ShadingModel::BlinnPhong};
constexpr Tonemap kTonemaps[] = {Tonemap::PbrNeutral, Tonemap::Aces, Tonemap::Agx, Tonemap::Reinhard,
                                 Tonemap::Linear};
// The forward pass's radiance clamp (forward.frag.glsl).
constexpr float kMaxRadiance = 60000.0f;
// 8-bit against the CPU tonemap: 1 level, for the float → UNORM rounding Vulkan leaves to the
// implementation and the GPU's pow/log2/exp2 against libm's. Measured on lavapipe: at most 1.
constexpr int kLdrTolerance = 1;

const char* shadingName(ShadingModel model) {
    return model == ShadingModel::Pbr ? "pbr" : model == ShadingModel::PbrSchlickGgx ? "pbr-schlick-ggx" : "blinn-phong";
}

glm::vec4 texel(const CapturedFrame& frame, size_t i) {
    return {frame.rgba32f[4 * i], frame.rgba32f[4 * i + 1], frame.rgba32f[4 * i + 2], frame.rgba32f[4 * i + 3]};
}

std::string where(const CapturedFrame& frame, size_t i) {
    return "pixel (" + std::to_string(i % frame.width) + ", " + std::to_string(i / frame.width) + ")";
}

// The first HDR value that is not finite or out of range, or "" if there is none.
std::string hdrProblem(const CapturedFrame& hdr) {
    for (size_t i = 0; i < hdr.rgba32f.size(); ++i) {
        const float v = hdr.rgba32f[i];
        const bool alpha = i % 4 == 3;
        if (!std::isfinite(v) || v < 0.0f || v > (alpha ? 1.0f : kMaxRadiance)) {
            std::ostringstream out;
            out << where(hdr, i / 4) << " channel " << i % 4 << " = " << v;
            return out.str();
        }
    }
    return {};
}

// The 8-bit pixel the tonemap pass must write for HDR texel `hdr` (no background: alpha = coverage).
glm::ivec4 expectedLdr(const glm::vec4& hdr, const passes::TonemapSettings& settings) {
    const float coverage = std::clamp(hdr.a, 0.0f, 1.0f);
    const glm::vec3 radiance = coverage > 0.0f ? glm::vec3(hdr) / coverage : glm::vec3(0.0f);
    const glm::vec3 display = shading::srgbEncode(
        shading::applyTonemap(radiance * std::exp2(settings.exposureEv), static_cast<uint32_t>(settings.op)));
    return glm::ivec4(glm::round(glm::clamp(glm::vec4(display, coverage), 0.0f, 1.0f) * 255.0f));
}

// The largest difference of `ldr` from the CPU tonemap of `hdr`, and where it is.
std::pair<int, size_t> ldrDifference(const CapturedFrame& hdr, const CapturedFrame& ldr,
                                     const passes::TonemapSettings& settings) {
    std::pair<int, size_t> worst{0, 0};
    for (size_t i = 0; i < size_t(ldr.width) * ldr.height; ++i) {
        const glm::ivec4 expected = expectedLdr(texel(hdr, i), settings);
        for (int c = 0; c < 4; ++c) {
            const int difference = std::abs(int(ldr.rgba8[4 * i + size_t(c)]) - expected[c]);
            if (difference > worst.first) worst = {difference, i};
        }
    }
    return worst;
}

// With CANDELA_TEST_OUTPUT set, writes the 8-bit captures there as TEST_N_MODEL_TONEMAP_EVev.png.
void maybeWrite(const CapturedFrame& ldr, ShadingModel model, Tonemap op, float ev) {
    const char* dir = std::getenv("CANDELA_TEST_OUTPUT");
    if (!dir) return;
    static int counter = 0;
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = std::string(test->name()) + "_" + std::to_string(counter++) + "_" + shadingName(model) +
                             "_" + options::tonemapName(op) + "_" + std::to_string(int(ev)) + "ev.png";
    assets::writePng(std::string(dir) + "/" + name, ldr.width, ldr.height, ldr.rgba8);
}

// Renders `settings.scene` with every shading model (HDR) and, for each, every tone mapping
// operator at each of `exposures` (EV; 8-bit), and checks them as described at the top. Returns the
// HDR frame of `pbr`.
CapturedFrame renderAndCheck(Renderer& renderer, RenderSettings settings,
                             std::initializer_list<float> exposures = {0.0f}) {
    settings.width = kWidth;
    settings.height = kHeight;
    CapturedFrame pbr;
    int worstLdr = 0;
    for (const ShadingModel model : kShadingModels) {
        SCOPED_TRACE(shadingName(model));
        settings.shading = model;
        settings.floatOutput = true;
        CapturedFrame hdr = renderer.capture(settings);
        EXPECT_EQ(hdrProblem(hdr), "");
        settings.floatOutput = false;
        for (const float ev : exposures)
            for (const Tonemap op : kTonemaps) {
                settings.tonemap.exposureEv = ev;
                settings.tonemap.op = op;
                const CapturedFrame ldr = renderer.capture(settings);
                maybeWrite(ldr, model, op, ev);
                const auto [difference, at] = ldrDifference(hdr, ldr, settings.tonemap);
                EXPECT_LE(difference, kLdrTolerance)
                    << options::tonemapName(op) << " at " << ev << " EV, " << where(ldr, at);
                worstLdr = std::max(worstLdr, difference);
            }
        if (model == ShadingModel::Pbr) pbr = std::move(hdr);
    }
    ::testing::Test::RecordProperty("maxLdrDifference", worstLdr);
    return pbr;
}

// Only the default shading model, HDR only, checked: for comparisons between renders.
CapturedFrame renderHdr(Renderer& renderer, RenderSettings settings) {
    settings.width = kWidth;
    settings.height = kHeight;
    settings.floatOutput = true;
    CapturedFrame hdr = renderer.capture(settings);
    EXPECT_EQ(hdrProblem(hdr), "");
    return hdr;
}

float maxRadiance(const CapturedFrame& hdr) {
    float out = 0.0f;
    for (size_t i = 0; i < hdr.rgba32f.size(); ++i)
        if (i % 4 != 3) out = std::max(out, hdr.rgba32f[i]);
    return out;
}

size_t coveredPixels(const CapturedFrame& hdr) {
    size_t covered = 0;
    for (size_t i = 0; i < size_t(hdr.width) * hdr.height; ++i) covered += texel(hdr, i).a > 0.5f ? 1 : 0;
    return covered;
}

// Per-pixel comparison of two HDR renders of the same view.
struct HdrDifference {
    size_t covered = 0;             // pixels with coverage > 0.5 in `a`
    size_t coverageMismatches = 0;  // pixels covered (> 0.5) in one render and not the other
    double meanRelative = 0.0;      // Σ|a − b| / Σ|a| over the RGB of pixels covered in both
    double maxRelative = 0.0;       // max |a − b| / max(|a|, |b|, kRadianceFloor) per channel there
    size_t worst = 0;               // pixel of maxRelative
};

// Radiance below this counts as black for relative differences.
constexpr double kRadianceFloor = 1e-2;

HdrDifference compareHdr(const CapturedFrame& a, const CapturedFrame& b) {
    HdrDifference d;
    double sumDifference = 0.0, sumA = 0.0;
    for (size_t i = 0; i < size_t(a.width) * a.height; ++i) {
        const glm::vec4 x = texel(a, i), y = texel(b, i);
        d.covered += x.a > 0.5f ? 1 : 0;
        if ((x.a > 0.5f) != (y.a > 0.5f)) ++d.coverageMismatches;
        if (x.a <= 0.5f || y.a <= 0.5f) continue;
        for (int c = 0; c < 3; ++c) {
            const double difference = std::abs(double(x[c]) - double(y[c]));
            sumDifference += difference;
            sumA += std::abs(double(x[c]));
            const double relative =
                difference / std::max({std::abs(double(x[c])), std::abs(double(y[c])), kRadianceFloor});
            if (relative > d.maxRelative) d.maxRelative = relative, d.worst = i;
        }
    }
    d.meanRelative = sumA > 0.0 ? sumDifference / sumA : 0.0;
    return d;
}

std::string describe(const HdrDifference& d, const CapturedFrame& frame) {
    std::ostringstream out;
    out << "covered " << d.covered << ", coverage mismatches " << d.coverageMismatches << ", mean relative "
        << d.meanRelative << ", max relative " << d.maxRelative << " at " << where(frame, d.worst);
    return out.str();
}

// compareHdr, with the result kept in the test's XML output (--gtest_output) as what was measured.
HdrDifference compareAndRecord(const std::string& what, const CapturedFrame& a, const CapturedFrame& b) {
    const HdrDifference d = compareHdr(a, b);
    ::testing::Test::RecordProperty(what, describe(d, b));
    return d;
}

// ---- Scenes --------------------------------------------------------------------------------------

enum class ScaleBy { Vertices, Transforms };

// `scene` uniformly scaled by k about the origin: either its vertex positions (and the draws'
// translations) or its draw transforms; bounds and light positions and ranges too. Point and spot
// intensities are multiplied by k² so that the irradiance (I / d²), hence the image, is unchanged.
scene::Scene scaled(scene::Scene scene, float k, ScaleBy by) {
    if (by == ScaleBy::Vertices) {
        for (scene::Vertex& v : scene.vertices) v.position *= k;
        for (scene::Draw& d : scene.draws) d.world[3] = glm::vec4(glm::vec3(d.world[3]) * k, 1.0f);
        // Errors of the levels of detail are in mesh units: they scale with the vertices.
        for (scene::LodChain& chain : scene.lodChains)
            for (scene::LodLevel& level : chain.levels) level.error *= k;
    } else {
        for (scene::Draw& d : scene.draws) d.world = glm::scale(glm::mat4(1.0f), glm::vec3(k)) * d.world;
    }
    for (scene::Draw& d : scene.draws) d.bounds.min *= k, d.bounds.max *= k;
    scene.bounds.min *= k;
    scene.bounds.max *= k;
    for (scene::Light& l : scene.lights) {
        l.position *= k;
        l.range *= k;
        if (l.type != scene::LightType::Directional) l.intensity *= k * k;
    }
    return scene;
}

// The sphere grid with roughness exactly 0 … 1 (bottom → top; the built-in grid starts at 0.05),
// metallic exactly 0 … 1 (left → right) and a white base colour (F0 = 1 exactly at metallic 1).
scene::Scene extremeMaterialGrid() {
    scene::Scene grid = assets::makeSphereGrid();
    for (size_t i = 0; i < grid.materials.size(); ++i) {
        grid.materials[i].roughnessFactor = float(i / 7) / 6.0f;
        grid.materials[i].baseColorFactor = glm::vec4(1.0f);
    }
    EXPECT_EQ(grid.materials.front().roughnessFactor, 0.0f);
    EXPECT_EQ(grid.materials.back().roughnessFactor, 1.0f);
    EXPECT_EQ(grid.materials.front().metallicFactor, 0.0f);
    EXPECT_EQ(grid.materials.back().metallicFactor, 1.0f);
    return grid;
}

scene::Light directional(glm::vec3 direction, float lux) {
    return {.type = scene::LightType::Directional, .intensity = lux, .direction = glm::normalize(direction)};
}

// Normal-mapped panels: six double-sided 1.8 m squares in the XY plane facing +Z (3 columns × 2
// rows, 2 m apart), each tilted by kTilt and with its own 1×1 normal texture and material.
enum class NormalData { Unit, Zero, Opposed };        // Opposed: ±Z alternating, the interpolant crosses 0
enum class TangentData { Unit, Zero, AlongNormal };  // AlongNormal: no component in the surface
struct PanelOptions {
    NormalData normals = NormalData::Unit;
    TangentData tangents = TangentData::Unit;
    bool normalTextures = true;  // false: the same materials without their normal texture
};

struct Panel {
    std::array<uint8_t, 4> normalTexel;  // tangent-space normal, n = texel / 255 · 2 − 1
    float normalScale;
    float metallic;
    float roughness;
};
constexpr Panel kPanels[] = {
    {{200, 90, 230, 255}, 1.0f, 1.0f, 0.0f},     // tilted, mirror-like metal
    {{0, 0, 0, 255}, 1.0f, 0.0f, 0.5f},          // (−1, −1, −1): into the surface, N·V < 0
    {{128, 128, 0, 255}, 1.0f, 1.0f, 0.0f},      // ≈ (0, 0, −1): straight back, N·V ≈ −1
    {{255, 128, 128, 255}, 1.0f, 0.0f, 1.0f},    // (1, 0, 0): in the surface plane, N·V ≈ 0
    {{200, 90, 230, 255}, 1e6f, 0.0f, 0.0f},     // tilted, normalScale 1e6 (the loader's limit)
    {{128, 128, 255, 255}, -1e6f, 0.5f, 0.2f},   // ≈ flat texel, normalScale −1e6: xy dominate
};

// 0.4 rad about an axis in the XY plane: off the coordinate axes, so that normals, tangents and
// the face normal from screen-space derivatives carry rounding like any real model's.
const glm::mat4 kTilt = glm::rotate(glm::mat4(1.0f), 0.4f, glm::normalize(glm::vec3(1.0f, 2.0f, 0.0f)));

scene::Scene normalMappedPanels(const PanelOptions& options) {
    scene::Scene scene;
    scene.source = "test: normal-mapped panels";
    constexpr float kHalf = 0.9f;
    const glm::vec2 corners[4] = {{-kHalf, -kHalf}, {kHalf, -kHalf}, {kHalf, kHalf}, {-kHalf, kHalf}};
    const glm::vec2 uvs[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    for (size_t p = 0; p < std::size(kPanels); ++p) {
        const Panel& panel = kPanels[p];
        scene.images.push_back({.name = "normal " + std::to_string(p),
                                .width = 1,
                                .height = 1,
                                .rgba8 = std::vector<uint8_t>(panel.normalTexel.begin(), panel.normalTexel.end())});
        scene::Material material{.name = "panel " + std::to_string(p),
                                 .metallicFactor = panel.metallic,
                                 .roughnessFactor = panel.roughness,
                                 .normalScale = panel.normalScale,
                                 .doubleSided = true};
        if (options.normalTextures) material.normal.image = int(p);
        scene.materials.push_back(material);

        const auto base = uint32_t(scene.vertices.size());
        for (int c = 0; c < 4; ++c) {
            scene::Vertex v;
            v.position = glm::vec3(corners[c], 0.0f);
            v.uv0 = uvs[c];
            v.normal = options.normals == NormalData::Zero      ? glm::vec3(0.0f)
                       : options.normals == NormalData::Opposed ? glm::vec3(0.0f, 0.0f, c % 2 ? -1.0f : 1.0f)
                                                                : glm::vec3(0.0f, 0.0f, 1.0f);
            v.tangent = options.tangents == TangentData::Zero          ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)
                        : options.tangents == TangentData::AlongNormal ? glm::vec4(0.0f, 0.0f, 1.0f, 1.0f)
                                                                       : glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
            scene.vertices.push_back(v);
        }
        scene::Draw draw{.firstIndex = uint32_t(scene.indices.size()), .indexCount = 6, .material = uint32_t(p)};
        scene.indices.insert(scene.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        const glm::vec3 offset((float(p % 3) - 1.0f) * 2.0f, (p < 3 ? 1.0f : -1.0f), 0.0f);
        draw.world = glm::translate(glm::mat4(1.0f), offset) * kTilt;
        for (const glm::vec2& corner : corners)
            draw.bounds.extend(glm::vec3(draw.world * glm::vec4(corner, 0.0f, 1.0f)));
        scene.bounds.extend(draw.bounds);
        scene.draws.push_back(draw);
    }
    // A key light from the front, a light from straight behind (toward the camera: V = −L for
    // normals flipped away from the viewer), a point light and a spot light in front.
    scene.lights.push_back(directional({-0.3f, -0.5f, -1.0f}, 3.0f));
    scene.lights.push_back(directional({0.0f, 0.0f, 1.0f}, 2.0f));
    scene.lights.push_back({.type = scene::LightType::Point, .intensity = 30.0f, .position = {0.0f, 0.0f, 2.5f}});
    scene.lights.push_back({.type = scene::LightType::Spot,
                            .intensity = 50.0f,
                            .innerConeAngle = 0.2f,
                            .outerConeAngle = 0.6f,
                            .position = {-2.0f, 1.0f, 3.0f},
                            .direction = glm::normalize(glm::vec3(2.0f, -1.0f, -3.0f))});
    return scene;
}

CameraSettings fromBehind() {
    CameraSettings camera;
    camera.orbit = glm::vec3(180.0f, 90.0f, 0.0f);  // θ = 180°: from −Z, framing the bounds
    return camera;
}

// The mirror image of fromBehind(): from +Z, on the horizon (the default view is 15° above it).
CameraSettings fromFront() {
    CameraSettings camera;
    camera.orbit = glm::vec3(0.0f, 90.0f, 0.0f);
    return camera;
}

// The renderer re-uploads a scene only when given a different Scene object (by address), and keeps
// pointing at the last one: every scene a test renders lives here, at its own address, until the
// test ends (after the test's Renderer).
class StabilityTest : public GpuTest {
protected:
    const scene::Scene* keep(scene::Scene scene) {
        mScenes.push_back(std::move(scene));
        return &mScenes.back();
    }
    void expectScaleInvariant(float k);

private:
    std::list<scene::Scene> mScenes;
};

// ---- Scale ---------------------------------------------------------------------------------------

// Scaled by 1e-3 and 1e4, the grid must look the same as at scale 1: the orbit camera frames the
// scaled bounds and the lights keep their irradiance. Tolerances, per render against scale 1:
//   - coverage: at most 1% of the covered pixels may change side of 0.5 (only pixels whose centre
//     lies on a silhouette within float rounding can);
//   - radiance over pixels covered in both: mean relative difference ≤ 1e-3, per channel ≤ 1e-2
//     (float rounding of positions, amplified by the roughness-0.05 highlights).
// Measured on lavapipe: no coverage change, mean ≤ 8.1e-6, max 9.6e-4.
void StabilityTest::expectScaleInvariant(float k) {
    Renderer renderer(context());
    const scene::Scene* reference = keep(assets::makeSphereGrid());
    const CapturedFrame unscaled = renderHdr(renderer, {.scene = reference});
    const size_t covered = coveredPixels(unscaled);
    // 49 unit spheres framed by the grid's bounding sphere cover about 12% of the image.
    EXPECT_GT(covered, size_t(kWidth * kHeight) * 8 / 100);
    for (const ScaleBy by : {ScaleBy::Vertices, ScaleBy::Transforms}) {
        SCOPED_TRACE(by == ScaleBy::Vertices ? "vertices scaled" : "transforms scaled");
        const CapturedFrame frame = renderAndCheck(renderer, {.scene = keep(scaled(*reference, k, by))});
        const HdrDifference d =
            compareAndRecord(by == ScaleBy::Vertices ? "verticesScaled" : "transformsScaled", unscaled, frame);
        EXPECT_LE(d.coverageMismatches, covered / 100) << describe(d, frame);
        EXPECT_LE(d.meanRelative, 1e-3) << describe(d, frame);
        EXPECT_LE(d.maxRelative, 1e-2) << describe(d, frame);
    }
}

TEST_F(StabilityTest, SphereGridScaledByOneThousandthKeepsCoverageAndRadiance) {
    expectScaleInvariant(1e-3f);
}

TEST_F(StabilityTest, SphereGridScaledByTenThousandKeepsCoverageAndRadiance) {
    expectScaleInvariant(1e4f);
}

// ---- Lights and materials ------------------------------------------------------------------------

TEST_F(StabilityTest, PointAndSpotLightsOfOneMillionCandela) {
    scene::Scene grid = extremeMaterialGrid();
    for (scene::Light& l : grid.lights) l.intensity = 1e6f;
    grid.lights.push_back({.type = scene::LightType::Spot,
                           .intensity = 1e6f,
                           .outerConeAngle = 0.5f,
                           .position = {0.0f, 0.0f, 6.0f},
                           .direction = {0.0f, 0.0f, -1.0f}});
    Renderer renderer(context());
    const scene::Scene* scene = keep(std::move(grid));
    for (const bool specularAa : {false, true}) {
        SCOPED_TRACE(specularAa ? "specular AA on" : "specular AA off");
        RenderSettings settings{.scene = scene};
        settings.shadingOptions.specularAntiAliasing = specularAa;
        // At 0 EV nearly everything saturates; −12 EV brings the diffuse spheres back inside the curves.
        const CapturedFrame hdr = renderAndCheck(renderer, settings, {0.0f, -12.0f});
        // The extreme reaches the image. Unfiltered, the roughness-0 highlights are narrower than a
        // pixel at this size, so the 60000 clamp is not reached; specular AA widens them to the
        // normal's spread over the pixel (α² ≥ 2σ²|∂n|²), spreading their peak (measured 7180).
        EXPECT_GT(maxRadiance(hdr), specularAa ? 1e3f : 1e4f);
    }
}

TEST_F(StabilityTest, DirectionalLightsOfOneMillionLux) {
    scene::Scene grid = extremeMaterialGrid();
    // Head-on, grazing the grid plane, and from behind (toward the camera).
    grid.lights = {directional({0.0f, 0.0f, -1.0f}, 1e6f), directional({1.0f, 0.0f, 0.0f}, 1e6f),
                   directional({0.0f, 0.0f, 1.0f}, 1e6f)};
    Renderer renderer(context());
    // −16 EV maps the radiance clamp (60000) to 0.92.
    const CapturedFrame hdr = renderAndCheck(renderer, {.scene = keep(std::move(grid))}, {0.0f, -16.0f});
    EXPECT_EQ(maxRadiance(hdr), kMaxRadiance);  // the extreme reaches the image: lit pixels hit the clamp
}

TEST_F(StabilityTest, RoughnessAndMetallicOfExactlyZeroAndOne) {
    Renderer renderer(context());
    const CapturedFrame hdr = renderAndCheck(renderer, {.scene = keep(extremeMaterialGrid())});
    EXPECT_GT(coveredPixels(hdr), size_t(kWidth * kHeight) * 8 / 100);
}

// ---- Degenerate normals and tangents, back faces -------------------------------------------------

// Zero-length vertex normals fall back to the geometric (face) normal. The panels are flat, so
// that is their vertex normal: the image must match the one with unit normals, seen from the front
// and (double-sided) from behind. Tolerance: identical coverage; mean relative difference ≤ 1e-3
// and per channel ≤ 1e-2 (the face normal comes from screen-space derivatives of the position,
// exact only up to float rounding, and the roughness-0 panels' highlights amplify a direction error).
// Measured on lavapipe: mean ≤ 2.6e-6, max 5.5e-4.
TEST_F(StabilityTest, ZeroLengthNormalsShadeWithTheGeometricNormal) {
    Renderer renderer(context());
    for (const bool normalTextures : {true, false}) {
        SCOPED_TRACE(normalTextures ? "normal-mapped" : "no normal map");
        const scene::Scene* reference = keep(normalMappedPanels({.normalTextures = normalTextures}));
        const scene::Scene* zero =
            keep(normalMappedPanels({.normals = NormalData::Zero, .normalTextures = normalTextures}));
        for (const CameraSettings& camera : {CameraSettings{}, fromBehind()}) {
            SCOPED_TRACE(camera.orbit ? "from behind" : "from the front");
            const CapturedFrame expected = renderHdr(renderer, {.scene = reference, .camera = camera});
            const CapturedFrame frame = renderAndCheck(renderer, {.scene = zero, .camera = camera});
            // Six 1.8 m panels framed by their bounding sphere cover about 20% of the image.
            EXPECT_GT(coveredPixels(frame), size_t(kWidth * kHeight) * 15 / 100);
            const HdrDifference d = compareAndRecord(std::string(normalTextures ? "mapped" : "plain") +
                                                         (camera.orbit ? "Behind" : "Front"), expected, frame);
            EXPECT_EQ(d.coverageMismatches, 0u) << describe(d, frame);
            EXPECT_LE(d.meanRelative, 1e-3) << describe(d, frame);
            EXPECT_LE(d.maxRelative, 1e-2) << describe(d, frame);
        }
    }
}

// A tangent with no component in the surface (zero, or along the normal) leaves the normal map
// out for that pixel: the image must match the same materials without normal textures.
// Tolerance: max relative difference per channel ≤ 1e-4 (same arithmetic, other pipeline variant).
// Measured on lavapipe: identical.
TEST_F(StabilityTest, TangentsWithoutASurfaceComponentLeaveTheNormalMapOut) {
    Renderer renderer(context());
    const CapturedFrame expected =
        renderHdr(renderer, {.scene = keep(normalMappedPanels({.normalTextures = false}))});
    for (const TangentData tangents : {TangentData::Zero, TangentData::AlongNormal}) {
        SCOPED_TRACE(tangents == TangentData::Zero ? "zero tangents" : "tangents along the normal");
        const CapturedFrame frame =
            renderAndCheck(renderer, {.scene = keep(normalMappedPanels({.tangents = tangents}))});
        const HdrDifference d =
            compareAndRecord(tangents == TangentData::Zero ? "zero" : "alongNormal", expected, frame);
        EXPECT_EQ(d.coverageMismatches, 0u) << describe(d, frame);
        EXPECT_LE(d.maxRelative, 1e-4) << describe(d, frame);
    }
}

TEST_F(StabilityTest, ZeroNormalsWithZeroTangentsAndNormalsInterpolatedThroughZero) {
    Renderer renderer(context());
    const scene::Scene* zero =
        keep(normalMappedPanels({.normals = NormalData::Zero, .tangents = TangentData::Zero}));
    const scene::Scene* opposed = keep(normalMappedPanels({.normals = NormalData::Opposed}));
    for (const scene::Scene* panels : {zero, opposed}) {
        SCOPED_TRACE(panels == zero ? "zero normals and tangents" : "opposed normals");
        for (const CameraSettings& camera : {CameraSettings{}, fromBehind()})
            renderAndCheck(renderer, {.scene = panels, .camera = camera});
    }
}

// Double-sided normal-mapped panels seen from behind: the shading normal is flipped toward the
// viewer, then four of the six normal textures tilt it (back) below the surface.
TEST_F(StabilityTest, BackFacingNormalMappedPanelsSeenFromBehind) {
    Renderer renderer(context());
    const scene::Scene* panels = keep(normalMappedPanels({}));
    const CapturedFrame front = renderAndCheck(renderer, {.scene = panels, .camera = fromFront()});
    const CapturedFrame back = renderAndCheck(renderer, {.scene = panels, .camera = fromBehind()});
    // The same panels cover the same number of pixels, mirrored left ↔ right.
    EXPECT_GT(coveredPixels(front), size_t(kWidth * kHeight) * 15 / 100);
    EXPECT_EQ(coveredPixels(back), coveredPixels(front));
}

// The panels at both scale extremes (draw transforms scaled, so normals and tangents reach the
// shader with lengths 1/k and k) against scale 1. Tolerance as for the sphere grid (coverage
// mismatches ≤ 1% of covered pixels, mean relative radiance difference ≤ 1e-3, per channel ≤ 1e-2).
// Measured on lavapipe: no coverage change, mean ≤ 7.7e-7, max 9.6e-4. (Tangents along the normal
// at scale 1e4 measured a mean of 0.78 before forward.frag.glsl's tangent threshold became relative.)
TEST_F(StabilityTest, NormalMappedPanelsAtBothScaleExtremes) {
    Renderer renderer(context());
    for (const PanelOptions& options : {PanelOptions{}, PanelOptions{.tangents = TangentData::AlongNormal},
                                        PanelOptions{.normals = NormalData::Zero}}) {
        const scene::Scene* reference = keep(normalMappedPanels(options));
        const CapturedFrame unscaled = renderHdr(renderer, {.scene = reference});
        const size_t covered = coveredPixels(unscaled);
        for (const float k : {1e-3f, 1e4f}) {
            SCOPED_TRACE("normals " + std::to_string(int(options.normals)) + ", tangents " +
                         std::to_string(int(options.tangents)) + ", scale " + std::to_string(k));
            const CapturedFrame frame =
                renderHdr(renderer, {.scene = keep(scaled(*reference, k, ScaleBy::Transforms))});
            const HdrDifference d = compareAndRecord("normals" + std::to_string(int(options.normals)) + "Tangents" +
                                                         std::to_string(int(options.tangents)) + "Scale" +
                                                         (k < 1.0f ? "1e-3" : "1e4"),
                                                     unscaled, frame);
            EXPECT_LE(d.coverageMismatches, covered / 100) << describe(d, frame);
            EXPECT_LE(d.meanRelative, 1e-3) << describe(d, frame);
            EXPECT_LE(d.maxRelative, 1e-2) << describe(d, frame);
        }
    }
}

}  // namespace
}  // namespace candela::test::stability_test
