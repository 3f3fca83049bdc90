// Points and lines (glTF modes POINTS, LINES, LINE_LOOP, LINE_STRIP) drawn on both shading paths
// (the visibility path draws them forward after its shading, forward_points_lines), at one sample
// and at four: MeshPrimitiveModes against the image its specification describes — every point and
// every segment drawn where it projects, nothing between them, the loop closed and the strip not —
// and points and lines with materials, vertex colours, morph targets, a skin and normals (lit when
// they have them, unshaded when not). Metric: the brightest pixel within one pixel of where a point
// or a segment's midpoint projects (lines are one pixel wide and may rasterize a pixel aside), and
// its colour, against thresholds with wide margins (drawn unshaded or lit: 8-bit values above 150,
// dark below 40).
#include "gpu_test.h"
#include "test_paths.h"

#include "animation_pointer_util.h"
#include "gltf_test_util.h"
#include "assets/gltf_loader.h"
#include "render/frame_builder.h"
#include "render/renderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <vector>

namespace candela::test::primitive_modes_test {
namespace {

constexpr uint32_t kWidth = 256, kHeight = 256;
using assets::test::GltfBuilder;
using assets::test::Json;
using Rgb = std::array<int, 3>;

class PrimitiveModesTest : public GpuTest {
protected:
    // A camera at `eye` looking at `target` (+Y up), 45° vertical field of view.
    void lookAt(glm::vec3 eye, glm::vec3 target) {
        mCamera.cameraToWorld = glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
        mCamera.fovYDegrees = 45.0f;
    }
    CapturedFrame render(const scene::Scene& scene, options::ShadingPath path, uint32_t samples) {
        if (!mRenderer) mRenderer = std::make_unique<Renderer>(context());
        RenderSettings settings{.width = kWidth, .height = kHeight, .scene = &scene};
        settings.camera = mCamera;
        settings.shadingPath = path;
        settings.msaa = samples;
        mView = FrameBuilder::resolveView(scene, mCamera, float(kWidth) / kHeight);
        CapturedFrame frame = mRenderer->capture(settings);
        EXPECT_EQ(mRenderer->lastPlan()->path, path);
        return frame;
    }
    bool declares(const std::string& pass) const { return mRenderer->lastGraph().findPass(pass).has_value(); }
    // The brightest pixel (by its largest channel) within one pixel of where world point `p` projects.
    Rgb brightestNear(const CapturedFrame& frame, glm::vec3 p) const {
        const glm::vec4 clip = mView.viewProjection * glm::vec4(p, 1.0f);
        const int cx = int(std::floor((clip.x / clip.w * 0.5f + 0.5f) * float(kWidth)));
        const int cy = int(std::floor((clip.y / clip.w * 0.5f + 0.5f) * float(kHeight)));
        Rgb best{-1, -1, -1};
        for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, int(kHeight) - 1); ++y)
            for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, int(kWidth) - 1); ++x) {
                const uint8_t* px = &frame.rgba8[(size_t(y) * kWidth + size_t(x)) * 4];
                const Rgb rgb{px[0], px[1], px[2]};
                if (*std::max_element(rgb.begin(), rgb.end()) > *std::max_element(best.begin(), best.end())) best = rgb;
            }
        return best;
    }
    int brightness(const CapturedFrame& frame, glm::vec3 p) const {
        const Rgb rgb = brightestNear(frame, p);
        return *std::max_element(rgb.begin(), rgb.end());
    }

    CameraSettings mCamera;
    scene::ViewSetup mView;
    std::unique_ptr<Renderer> mRenderer;
};

// World position of index `i` of draw `d`.
glm::vec3 corner(const scene::Scene& s, const scene::Draw& d, uint32_t i) {
    return glm::vec3(d.world * glm::vec4(s.vertices[s.indices[d.firstIndex + i]].position, 1.0f));
}

TEST_F(PrimitiveModesTest, MeshPrimitiveModesDrawsEveryPrimitiveOnBothPaths) {
    const std::filesystem::path file = sharedAssets() / "models/MeshPrimitiveModes/glTF/MeshPrimitiveModes.gltf";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "no shared assets: " << file;
    const scene::Scene s = assets::loadGltf(file);
    ASSERT_EQ(s.draws.size(), 7u);
    lookAt({0, 0, 12}, {0, 0, 0});
    // The hexagon's centre and corners in the file's local space (README of the sample).
    const glm::vec3 centreOf[7] = {{0, 3, 0}, {-2, 0, 0}, {0, 0, 0}, {2, 0, 0}, {-2, -3, 0}, {0, -3, 0}, {2, -3, 0}};
    for (const options::ShadingPath path : shadingPaths())
        for (const uint32_t samples : {1u, 4u}) {
            SCOPED_TRACE(std::string(path == options::ShadingPath::Forward ? "forward" : "visibility") + ", msaa " + std::to_string(samples));
            const CapturedFrame frame = render(s, path, samples);
            EXPECT_EQ(declares("forward_points_lines"), path == options::ShadingPath::Visibility);
            // POINTS: each of the 7 points drawn, nothing halfway between a corner and the centre.
            const scene::Draw& points = s.draws[0];
            for (uint32_t i = 0; i < 7; ++i) EXPECT_GT(brightness(frame, corner(s, points, i)), 150) << "point " << i;
            for (uint32_t i = 1; i < 7; ++i)
                EXPECT_LT(brightness(frame, 0.5f * (corner(s, points, 0) + corner(s, points, i))), 40) << "between points " << i;
            // LINES, LINE_LOOP, LINE_STRIP: every segment's midpoint drawn (unshaded: the default
            // material's white), the middle of the hexagon's outer triangles not.
            for (size_t d = 1; d <= 3; ++d) {
                const scene::Draw& lines = s.draws[d];
                ASSERT_EQ(lines.topology, scene::Topology::Lines);
                for (uint32_t i = 0; i < lines.indexCount; i += 2) {
                    const Rgb mid = brightestNear(frame, 0.5f * (corner(s, lines, i) + corner(s, lines, i + 1)));
                    EXPECT_GT(std::min({mid[0], mid[1], mid[2]}), 150) << "draw " << d << " segment " << i / 2;
                }
                EXPECT_LT(brightness(frame, centreOf[d] + glm::vec3(0.6f, 0.0f, 0.0f) * 0.95f), 40) << "inside draw " << d;
            }
            // The loop closes from its last index (6, at the bottom) to its first (0, the centre);
            // the strip does not.
            EXPECT_GT(brightness(frame, centreOf[2] + glm::vec3(0, -0.5f, 0)), 150);
            EXPECT_LT(brightness(frame, centreOf[3] + glm::vec3(0, -0.5f, 0)), 40);
            // The triangles, strip and fan: filled, and lit (flat normals facing the camera, the
            // default lights: 122–123 measured at the time of writing), not unshaded.
            for (size_t d = 4; d < 7; ++d) {
                const int lit = brightness(frame, centreOf[d] + glm::vec3(0.3f, 0.3f, 0));
                EXPECT_GT(lit, 80) << "draw " << d;
                EXPECT_LT(lit, 200) << "draw " << d;
            }
        }
}

// Lines and points built for the test, each at its own height across the image (x from -2 to 2):
//   y  2.6  LINES with NORMAL facing away from the light (lit: dark)
//   y  2.2  LINES with NORMAL facing the light (lit: bright)
//   y  3.0  POINTS at x = ±1 with COLOR_0 green
//   y  1.5  LINE_STRIP with COLOR_0 red, default material
//   y  0.5  LINES, material base colour blue
//   y -0.5  LINES with a morph target moving it by -0.5 (weight 1): drawn at y -1.0
//   y -1.5  LINES skinned to a joint translated by -0.7: drawn at y -2.2
scene::Scene linesScene(const std::filesystem::path& dir) {
    GltfBuilder b;
    const auto across = [&](float y) { return b.addFloats({-2, y, 0, 2, y, 0}, "VEC3", 3); };
    const auto twice = [&](std::vector<float> v) {
        std::vector<float> out = v;
        out.insert(out.end(), v.begin(), v.end());
        return out;
    };
    b.doc["materials"] = Json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 1, 1}}}}},
                                      {{"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 1}}}}});
    const int line = b.addIndices({0, 1});
    std::vector<int> roots;
    const auto node = [&](int mesh) {
        roots.push_back(b.addNode({{"mesh", mesh}}));
        return roots.back();
    };
    node(b.addMesh({{"POSITION", across(2.6f)}, {"NORMAL", b.addFloats(twice({0, 0, -1}), "VEC3", 3)}}, line, 1, 1));
    node(b.addMesh({{"POSITION", across(2.2f)}, {"NORMAL", b.addFloats(twice({0, 0, 1}), "VEC3", 3)}}, line, 1, 1));
    node(b.addMesh({{"POSITION", b.addFloats({-1, 3, 0, 1, 3, 0}, "VEC3", 3)}, {"COLOR_0", b.addFloats(twice({0, 1, 0}), "VEC3", 3)}},
                   -1, -1, 0));
    node(b.addMesh({{"POSITION", across(1.5f)}, {"COLOR_0", b.addFloats(twice({1, 0, 0}), "VEC3", 3)}}, -1, -1, 3));
    node(b.addMesh({{"POSITION", across(0.5f)}}, line, 0, 1));
    const int morphed = b.addMesh({{"POSITION", across(-0.5f)}}, line, -1, 1);
    b.doc["meshes"][size_t(morphed)]["primitives"][0]["targets"] =
        Json::array({{{"POSITION", b.addFloats(twice({0, -0.5f, 0}), "VEC3", 3)}}});
    b.doc["nodes"][size_t(node(morphed))]["weights"] = {1.0};
    // The skin: both vertices on joint 0, a root node moved down.
    const std::vector<uint8_t> joints(8, 0);
    const int jointsAccessor = b.addAccessor(b.addView(joints), assets::test::kUnsignedByte, 2, "VEC4");
    const int skinned = b.addMesh({{"POSITION", across(-1.5f)}, {"JOINTS_0", jointsAccessor},
                                   {"WEIGHTS_0", b.addFloats({1, 0, 0, 0, 1, 0, 0, 0}, "VEC4", 4)}},
                                  line, -1, 1);
    const int joint = b.addNode({{"translation", {0, -0.7, 0}}});
    b.doc["skins"] = Json::array({{{"joints", {joint}}}});
    b.doc["nodes"][size_t(node(skinned))]["skin"] = 0;
    roots.push_back(joint);
    // A directional light shining down -Z (from the camera's side).
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = Json::array({{{"type", "directional"}, {"intensity", 3}}});
    assets::test::useExtension(b, "KHR_lights_punctual");
    roots.push_back(b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}));
    b.setScene(roots);
    return assets::loadGltf(b.writeGltf(dir, "lines"));
}

TEST_F(PrimitiveModesTest, PointsAndLinesWearMaterialsColoursMorphsAndSkinsOnBothPaths) {
    TempDir dir;
    const scene::Scene s = linesScene(dir.path());
    ASSERT_EQ(s.draws.size(), 7u);
    EXPECT_TRUE(s.report.warnings.empty()) << s.report.warnings.front();
    lookAt({0, 0.4f, 9}, {0, 0.4f, 0});
    for (const options::ShadingPath path : shadingPaths()) {
        SCOPED_TRACE(path == options::ShadingPath::Forward ? "forward" : "visibility");
        const CapturedFrame frame = render(s, path, 1);
        const auto at = [&](float x, float y) { return brightestNear(frame, {x, y, 0}); };
        for (const float x : {-1.5f, 0.5f}) {
            SCOPED_TRACE("x " + std::to_string(x));
            // Lit by their normals: facing the light bright, facing away dark.
            EXPECT_GT(brightness(frame, {x, 2.2f, 0}), 150);
            EXPECT_LT(brightness(frame, {x, 2.6f, 0}), 40);
            // COLOR_0 red on the default material; the blue material's base colour.
            const Rgb red = at(x, 1.5f), blue = at(x, 0.5f);
            EXPECT_GT(red[0], 150);
            EXPECT_LT(std::max(red[1], red[2]), 40);
            EXPECT_GT(blue[2], 150);
            EXPECT_LT(std::max(blue[0], blue[1]), 40);
            // Morphed from -0.5 to -1.0; skinned from -1.5 to -2.2.
            EXPECT_GT(brightness(frame, {x, -1.0f, 0}), 150);
            EXPECT_LT(brightness(frame, {x, -0.5f, 0}), 40);
            EXPECT_GT(brightness(frame, {x, -2.2f, 0}), 150);
            EXPECT_LT(brightness(frame, {x, -1.5f, 0}), 40);
        }
        // Green points, nothing between them.
        for (const float x : {-1.0f, 1.0f}) {
            const Rgb green = at(x, 3.0f);
            EXPECT_GT(green[1], 150);
            EXPECT_LT(std::max(green[0], green[2]), 40);
        }
        EXPECT_LT(brightness(frame, {0, 3.0f, 0}), 40);
    }
}

}  // namespace
}  // namespace candela::test::primitive_modes_test
