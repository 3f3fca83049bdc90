// Debug views of the forward pass (options/debug_view.h) on the built-in sphere grid: data is shown
// as its value, the lobes add up to the image, and the graph variant leaves out the skybox.
#include "gpu_test.h"

#include "assets/builtin_scenes.h"
#include "assets/procedural_sky.h"
#include "render/renderer.h"
#include "shared/tonemap.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace candela::test::debug_view_test {
namespace {

constexpr uint32_t kWidth = 480, kHeight = 270;

class DebugViewTest : public GpuTest {
protected:
    // `scene`: the grid by default; another scene must keep the grid's draws (sphereCentre reads them).
    CapturedFrame render(options::DebugView view, bool floatOutput = false, const scene::Scene* scene = nullptr) {
        RenderSettings settings{.width = kWidth, .height = kHeight, .floatOutput = floatOutput, .scene = scene ? scene : &mGrid};
        settings.debugView = view;
        return renderer().capture(settings);
    }
    Renderer& renderer() {
        if (!mRenderer) mRenderer = std::make_unique<Renderer>(context());
        return *mRenderer;
    }
    // The pixel at the centre of the sphere of `row` (0: bottom) and `column` (0: left).
    glm::ivec2 sphereCentre(int row, int column) const {
        const scene::Draw& draw = mGrid.draws[size_t(row) * 7 + size_t(column)];
        const glm::vec3 centre = 0.5f * (draw.bounds.min + draw.bounds.max);
        const scene::ViewSetup view = Renderer::resolveView(mGrid, {}, float(kWidth) / float(kHeight));
        const glm::vec4 clip = view.viewProjection * glm::vec4(centre, 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return {int((ndc.x * 0.5f + 0.5f) * kWidth), int((ndc.y * 0.5f + 0.5f) * kHeight)};
    }
    static const uint8_t* pixel(const CapturedFrame& frame, glm::ivec2 p) {
        return frame.rgba8.data() + (size_t(p.y) * frame.width + size_t(p.x)) * 4;
    }

    scene::Scene mGrid = assets::makeSphereGrid();
    std::unique_ptr<Renderer> mRenderer;
};

TEST_F(DebugViewTest, MetallicAndRoughnessAreShownAsTheirValues) {
    const CapturedFrame metallic = render(options::DebugView::Metallic);
    const CapturedFrame roughness = render(options::DebugView::Roughness);
    for (int row = 0; row < 7; ++row)
        for (int column = 0; column < 7; ++column) {
            const scene::Material& m = mGrid.materials[mGrid.draws[size_t(row) * 7 + size_t(column)].material];
            const glm::ivec2 p = sphereCentre(row, column);
            EXPECT_NEAR(pixel(metallic, p)[0], 255.0f * m.metallicFactor, 1.0f) << row << "," << column;
            EXPECT_NEAR(pixel(roughness, p)[1], 255.0f * m.roughnessFactor, 1.0f) << row << "," << column;
        }
}

TEST_F(DebugViewTest, NormalsFaceTheCameraAtSphereCentresAndBaseColourIsTheFactor) {
    const CapturedFrame normals = render(options::DebugView::GeometricNormal);
    const CapturedFrame mapped = render(options::DebugView::MappedNormal);  // no normal maps: the same
    const CapturedFrame base = render(options::DebugView::BaseColor);
    const scene::ViewSetup view = Renderer::resolveView(mGrid, {}, float(kWidth) / float(kHeight));
    const glm::ivec2 p = sphereCentre(3, 3);
    const glm::vec3 n = glm::normalize(view.eye - glm::vec3(0.0f));  // the middle sphere sits at the origin
    // Within the tessellated sphere's interpolated normals (≈ 0.05) of the true one; an sRGB-encoded
    // 0.5 would read 188, not 128.
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(pixel(normals, p)[c], 255.0f * (n[c] * 0.5f + 0.5f), 8.0f) << c;
        EXPECT_EQ(pixel(mapped, p)[c], pixel(normals, p)[c]);
    }
    const glm::vec3 srgb = shading::srgbEncode(glm::vec3(mGrid.materials[0].baseColorFactor));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(pixel(base, p)[c], 255.0f * srgb[c], 1.0f) << c;
}

TEST_F(DebugViewTest, DiffuseAndSpecularAddUpToTheImage) {
    const CapturedFrame image = render(options::DebugView::None, true);
    const CapturedFrame diffuse = render(options::DebugView::Diffuse, true);
    const CapturedFrame specular = render(options::DebugView::Specular, true);
    size_t compared = 0;
    double worst = 0.0;
    for (size_t i = 0; i < image.rgba32f.size(); ++i) {
        if (i % 4 == 3) continue;
        const double sum = double(diffuse.rgba32f[i]) + specular.rgba32f[i];
        worst = std::max(worst, std::abs(sum - image.rgba32f[i]) / (std::abs(image.rgba32f[i]) + 1e-2));
        ++compared;
    }
    EXPECT_GT(compared, 0u);
    EXPECT_LT(worst, 4e-3);  // three half-float roundings
}

TEST_F(DebugViewTest, LayerLightsAddUpWithTheLobesAndTheCoatNormalIsShown) {
    // The grid under a sheen (0.9, 0.6, 0.3; roughness 0.4) and a coat (weight 1, roughness 0.2, no
    // normal map of its own): the material's lobes beneath them plus the sheen's and the coat's
    // light make the image; the coat's normal is the unmapped one. Without layers, the layer views
    // are black.
    const CapturedFrame bare = render(options::DebugView::Clearcoat);
    const CapturedFrame bareNormal = render(options::DebugView::ClearcoatNormal);
    const CapturedFrame bareSheen = render(options::DebugView::Sheen);
    for (int row = 0; row < 7; ++row)
        for (int column = 0; column < 7; ++column)
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(pixel(bare, sphereCentre(row, column))[c], 0) << row << "," << column;
                EXPECT_EQ(pixel(bareNormal, sphereCentre(row, column))[c], 0) << row << "," << column;
                EXPECT_EQ(pixel(bareSheen, sphereCentre(row, column))[c], 0) << row << "," << column;
            }
    scene::Scene coated = mGrid;
    for (scene::Material& m : coated.materials) {
        m.clearcoatFactor = 1.0f, m.clearcoatRoughnessFactor = 0.2f;
        m.sheenColorFactor = glm::vec3(0.9f, 0.6f, 0.3f), m.sheenRoughnessFactor = 0.4f;
    }
    const CapturedFrame image = render(options::DebugView::None, true, &coated);
    const CapturedFrame diffuse = render(options::DebugView::Diffuse, true, &coated);
    const CapturedFrame specular = render(options::DebugView::Specular, true, &coated);
    const CapturedFrame coat = render(options::DebugView::Clearcoat, true, &coated);
    const CapturedFrame sheen = render(options::DebugView::Sheen, true, &coated);
    double worst = 0.0, coatTotal = 0.0, sheenTotal = 0.0;
    for (size_t i = 0; i < image.rgba32f.size(); ++i) {
        if (i % 4 == 3) continue;
        const double sum = double(diffuse.rgba32f[i]) + specular.rgba32f[i] + coat.rgba32f[i] + sheen.rgba32f[i];
        worst = std::max(worst, std::abs(sum - image.rgba32f[i]) / (std::abs(image.rgba32f[i]) + 1e-2));
        coatTotal += coat.rgba32f[i];
        sheenTotal += sheen.rgba32f[i];
    }
    EXPECT_GT(coatTotal, 0.0);
    EXPECT_GT(sheenTotal, 0.0);
    EXPECT_LT(worst, 6e-3);  // five half-float roundings
    const CapturedFrame normals = render(options::DebugView::GeometricNormal, false, &coated);
    const CapturedFrame coatNormals = render(options::DebugView::ClearcoatNormal, false, &coated);
    const glm::ivec2 p = sphereCentre(3, 3);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(pixel(coatNormals, p)[c], pixel(normals, p)[c]) << c;
}

TEST_F(DebugViewTest, GgxTermsStayInTheirRanges) {
    const CapturedFrame d = render(options::DebugView::D);
    const CapturedFrame g = render(options::DebugView::G);
    const CapturedFrame f = render(options::DebugView::F);
    // Dielectric, smooth: F at least F0 = 0.04 where the first light reaches; G close to 1 facing it.
    const glm::ivec2 p = sphereCentre(0, 0);
    EXPECT_GE(pixel(f, p)[0], uint8_t(0.04f * 255.0f) - 1);
    EXPECT_GT(pixel(g, p)[0], 200);
    // D relative to its peak: the highlight of the smoothest row reaches 1 somewhere.
    uint8_t peak = 0;
    for (size_t i = 0; i < d.rgba8.size(); i += 4) peak = std::max(peak, d.rgba8[i]);
    EXPECT_EQ(peak, 255);
}

TEST_F(DebugViewTest, IsAGraphVariantWithoutTheSkybox) {
    const assets::Environment sky = assets::makeProceduralSky();
    RenderSettings settings{.width = 64, .height = 36, .scene = &mGrid};
    settings.environment = &sky;
    settings.iblQuality.cubeSize = 64;
    settings.debugView = options::DebugView::Roughness;
    renderer().capture(settings);
    EXPECT_FALSE(renderer().lastGraph().findPass("skybox").has_value());
    const std::vector<std::string> lines = renderer().explain();
    EXPECT_NE(std::find(lines.begin(), lines.end(), "debug view: roughness (shown as data: linear tonemap at exposure 0)"),
              lines.end());
    EXPECT_NE(std::find(lines.begin(), lines.end(), "left out: skybox (debug view)"), lines.end());
    // Without the debug view the sky is back: composited by the tonemap (depth-tested at one
    // sample, the grid having no blended draws, under the resolved image with MSAA, a GPU's
    // default), or by the skybox pass into a float capture.
    settings.debugView = options::DebugView::None;
    renderer().capture(settings);
    const std::vector<std::string> shaded = renderer().explain();
    const std::string skyLine = renderer().msaa(settings.msaa).samples == 1
                                ? "sky: composited by the tonemap where nothing was drawn (depth-tested, the image not "
                                  "read there: no blended draws; no skybox pass)"
                                : "sky: composited under the image by the tonemap (no skybox pass)";
    EXPECT_NE(std::find(shaded.begin(), shaded.end(), skyLine), shaded.end());
    settings.floatOutput = true;
    renderer().capture(settings);
    EXPECT_TRUE(renderer().lastGraph().findPass("skybox").has_value());
}

}  // namespace
}  // namespace candela::test::debug_view_test
