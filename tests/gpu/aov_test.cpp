// The per-pixel outputs (docs/outputs.md): depth and normals against a ray cast in double
// precision through each pixel centre (a plane and a tessellated sphere: their triangles, and the
// analytic sphere within its tessellation), the empty pixels, the clip depth against the view depth,
// coverage equal to the colour image's on both shading paths, the outputs equal between the paths,
// IDs against the draw list (a hidden node never appears; instances), and no aov pass without outputs.
#include "gpu_test.h"
#include "test_paths.h"

#include "assets/builtin_scenes.h"
#include "assets/gltf_loader.h"
#include "render/frame_builder.h"
#include "render/renderer.h"
#include "shared/scene_data.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace candela::test::aov_test {
namespace {

using options::PixelOutput;
constexpr uint32_t kWidth = 192, kHeight = 128;
constexpr glm::dvec3 kSphereCentre{0.2, -0.1, 0.6};
constexpr double kSphereRadius = 0.5;

// A 4 × 4 plane at z = 0 (node 7, mesh 2) and a UV sphere above it (node 3, mesh 5, primitive 1),
// each with its own material.
scene::Scene planeAndSphere() {
    scene::Scene s;
    s.source = "built-in: plane and sphere";
    for (glm::vec2 corner : {glm::vec2(-2, -2), glm::vec2(2, -2), glm::vec2(2, 2), glm::vec2(-2, 2)})
        s.vertices.push_back({.position = glm::vec3(corner, 0.0f), .normal = {0, 0, 1}});
    s.indices = {0, 1, 2, 0, 2, 3};
    const uint32_t sphereFirst = uint32_t(s.vertices.size());
    constexpr uint32_t kRings = 48, kSegments = 96;
    for (uint32_t r = 0; r <= kRings; ++r)
        for (uint32_t g = 0; g <= kSegments; ++g) {
            const double theta = M_PI * r / kRings, phi = 2.0 * M_PI * g / kSegments;
            const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
            s.vertices.push_back({.position = glm::vec3(kSphereCentre + kSphereRadius * n), .normal = glm::vec3(n)});
        }
    const uint32_t sphereIndex = uint32_t(s.indices.size());
    for (uint32_t r = 0; r < kRings; ++r)
        for (uint32_t g = 0; g < kSegments; ++g) {
            const uint32_t a = sphereFirst + r * (kSegments + 1) + g, b = a + kSegments + 1;
            // Counter-clockwise seen from outside.
            for (uint32_t i : {a, b, a + 1, a + 1, b, b + 1}) s.indices.push_back(i);
        }
    s.materials = {scene::Material{.name = "plane"}, scene::Material{.name = "sphere"}};
    for (int i = 0; i < 8; ++i) s.nodes.push_back({.name = "n" + std::to_string(i), .source = i});
    scene::Draw plane{.firstIndex = 0, .indexCount = 6, .material = 0, .node = 7, .mesh = 2, .primitive = 0};
    plane.localBounds = plane.bounds = scene::Aabb{glm::vec3(-2, -2, 0), glm::vec3(2, 2, 0)};
    scene::Draw sphere{.firstIndex = sphereIndex, .indexCount = uint32_t(s.indices.size()) - sphereIndex, .material = 1, .node = 3,
                       .mesh = 5, .primitive = 1};
    sphere.localBounds = sphere.bounds = scene::Aabb{glm::vec3(kSphereCentre - kSphereRadius), glm::vec3(kSphereCentre + kSphereRadius)};
    s.draws = {plane, sphere};
    s.bounds = plane.bounds;
    s.bounds.extend(sphere.bounds.max);
    return s;
}

template <typename T>
const std::vector<T>& valuesOf(const CapturedFrame& frame, PixelOutput output);
template <>
const std::vector<float>& valuesOf(const CapturedFrame& frame, PixelOutput output) {
    for (const CapturedOutput& o : frame.outputs)
        if (o.output == output) return o.floats;
    throw std::logic_error("output not captured");
}
template <>
const std::vector<uint32_t>& valuesOf(const CapturedFrame& frame, PixelOutput output) {
    for (const CapturedOutput& o : frame.outputs)
        if (o.output == output) return o.ids;
    throw std::logic_error("output not captured");
}

class AovTest : public GpuTest {
protected:
    Renderer& renderer() {
        if (!mRenderer) mRenderer = std::make_unique<Renderer>(context());
        return *mRenderer;
    }
    CapturedFrame render(const scene::Scene& scene, options::PixelOutputs outputs, options::ShadingPath path = options::ShadingPath::Forward,
                         uint32_t msaa = 1) {
        RenderSettings settings{.width = kWidth, .height = kHeight, .scene = &scene};
        settings.camera = mCamera;
        settings.outputs = outputs;
        settings.shadingPath = path;
        settings.msaa = msaa;
        return renderer().capture(settings);
    }
    bool declares(const std::string& pass) const { return mRenderer->lastGraph().findPass(pass).has_value(); }

    CameraSettings mCamera;
    std::unique_ptr<Renderer> mRenderer;
};

// The nearest hit of the ray o + t·d with `scene`'s triangles (double precision): t, the draw and
// the barycentric-interpolated vertex normal.
struct Hit {
    double t = std::numeric_limits<double>::infinity();
    int draw = -1;
    glm::dvec3 normal{0.0};
    double edge = 1.0;  // the smallest barycentric: how far inside its triangle the hit is
};
Hit castRay(const scene::Scene& s, const glm::dvec3& o, const glm::dvec3& d) {
    Hit best;
    for (int di = 0; di < int(s.draws.size()); ++di) {
        const scene::Draw& draw = s.draws[size_t(di)];
        for (uint32_t i = draw.firstIndex; i < draw.firstIndex + draw.indexCount; i += 3) {
            const scene::Vertex& va = s.vertices[s.indices[i]];
            const scene::Vertex& vb = s.vertices[s.indices[i + 1]];
            const scene::Vertex& vc = s.vertices[s.indices[i + 2]];
            const glm::dvec3 a(va.position), e1 = glm::dvec3(vb.position) - a, e2 = glm::dvec3(vc.position) - a;
            const glm::dvec3 p = glm::cross(d, e2);
            const double det = glm::dot(e1, p);
            if (std::abs(det) < 1e-18) continue;
            const glm::dvec3 q = o - a;
            const double u = glm::dot(q, p) / det;
            const glm::dvec3 r = glm::cross(q, e1);
            const double v = glm::dot(d, r) / det, t = glm::dot(e2, r) / det;
            if (u < 0 || v < 0 || u + v > 1 || t <= 0 || t >= best.t) continue;
            best = {t, di, glm::normalize((1 - u - v) * glm::dvec3(va.normal) + u * glm::dvec3(vb.normal) + v * glm::dvec3(vc.normal)),
                    std::min({u, v, 1 - u - v})};
        }
    }
    return best;
}

// The distance in pixels from (px, py) to the nearest edge of `scene`'s triangles projected by
// `viewProjection` onto a width × height image (pixel centres at half-integers, as the ray cast).
double pixelsToNearestEdge(const scene::Scene& s, const glm::dmat4& viewProjection, double px, double py) {
    auto project = [&](const glm::vec3& p) {
        const glm::dvec4 c = viewProjection * glm::dvec4(glm::dvec3(p), 1.0);
        return glm::dvec2((c.x / c.w + 1) * 0.5 * kWidth, (c.y / c.w + 1) * 0.5 * kHeight);
    };
    auto toSegment = [&](glm::dvec2 a, glm::dvec2 b) {
        const glm::dvec2 ab = b - a, ap = glm::dvec2(px, py) - a;
        const double t = std::clamp(glm::dot(ap, ab) / std::max(glm::dot(ab, ab), 1e-300), 0.0, 1.0);
        return glm::length(ap - t * ab);
    };
    double nearest = std::numeric_limits<double>::infinity();
    for (const scene::Draw& draw : s.draws)
        for (uint32_t i = draw.firstIndex; i < draw.firstIndex + draw.indexCount; i += 3) {
            const glm::dvec2 a = project(s.vertices[s.indices[i]].position), b = project(s.vertices[s.indices[i + 1]].position),
                             c = project(s.vertices[s.indices[i + 2]].position);
            nearest = std::min({nearest, toSegment(a, b), toSegment(b, c), toSegment(c, a)});
        }
    return nearest;
}

TEST_F(AovTest, DepthAndNormalsMatchARayCastThroughEachPixelCentre) {
    const scene::Scene scene = planeAndSphere();
    const glm::vec3 eye(1.2f, -2.6f, 3.4f);
    mCamera.cameraToWorld = glm::inverse(glm::lookAt(eye, glm::vec3(0.1f, 0.0f, 0.3f), glm::vec3(0, 0, 1)));
    mCamera.fovYDegrees = 40.0f;
    const CapturedFrame frame = render(scene, {PixelOutput::Depth, PixelOutput::ClipDepth, PixelOutput::Normal, PixelOutput::NodeId,
                                               PixelOutput::MeshId, PixelOutput::PrimitiveId, PixelOutput::MaterialId, PixelOutput::InstanceId});
    const auto& depth = valuesOf<float>(frame, PixelOutput::Depth);
    const auto& clip = valuesOf<float>(frame, PixelOutput::ClipDepth);
    const auto& normal = valuesOf<float>(frame, PixelOutput::Normal);
    const auto& node = valuesOf<uint32_t>(frame, PixelOutput::NodeId);
    const auto& mesh = valuesOf<uint32_t>(frame, PixelOutput::MeshId);
    const auto& primitive = valuesOf<uint32_t>(frame, PixelOutput::PrimitiveId);
    const auto& material = valuesOf<uint32_t>(frame, PixelOutput::MaterialId);
    const auto& instance = valuesOf<uint32_t>(frame, PixelOutput::InstanceId);

    const scene::ViewSetup view = FrameBuilder::resolveView(scene, mCamera, float(kWidth) / kHeight);
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(view.viewProjection)), worldToView = glm::dmat4(view.view);
    double planeError = 0, sphereError = 0, sphereAnalytic = 0, normalError = 0, analyticNormal = 0, clipError = 0;
    uint32_t plane = 0, sphere = 0, empty = 0, silhouette = 0;
    std::vector<Hit> hits(size_t(kWidth) * kHeight);
    std::vector<glm::dvec3> origins(hits.size()), directions(hits.size());
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const size_t i = size_t(y) * kWidth + x;
            const glm::dvec2 ndc((x + 0.5) / kWidth * 2 - 1, (y + 0.5) / kHeight * 2 - 1);
            const glm::dvec4 nearH = inverse * glm::dvec4(ndc, 1.0, 1.0), farH = inverse * glm::dvec4(ndc, 0.5, 1.0);
            origins[i] = glm::dvec3(nearH) / nearH.w;
            directions[i] = glm::normalize(glm::dvec3(farH) / farH.w - origins[i]);
            hits[i] = castRay(scene, origins[i], directions[i]);
        }
    // The rasterizer snaps vertices to 1/2^subPixelPrecisionBits of a pixel (8 bits on lavapipe, 4 on
    // SwiftShader), which moves a triangle's edges by up to √2 of that step: a pixel centre that
    // close to an edge between two draws (or a draw and the background) may fall to either side.
    const double snap = std::sqrt(2.0) / double(1u << context().properties().limits.subPixelPrecisionBits);
    auto onSilhouette = [&](uint32_t x, uint32_t y) {
        const int draw = hits[size_t(y) * kWidth + x].draw;
        bool boundary = false;
        for (auto [dx, dy] : {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}}) {
            const int nx = int(x) + dx, ny = int(y) + dy;
            if (nx >= 0 && ny >= 0 && nx < int(kWidth) && ny < int(kHeight) && hits[size_t(ny) * kWidth + size_t(nx)].draw != draw)
                boundary = true;
        }
        return boundary && pixelsToNearestEdge(scene, glm::dmat4(view.viewProjection), x + 0.5, y + 0.5) < snap;
    };
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const size_t i = size_t(y) * kWidth + x;
            const glm::dvec3 origin = origins[i], direction = directions[i];
            const Hit& hit = hits[i];
            if (onSilhouette(x, y)) {
                ++silhouette;
                continue;
            }
            if (hit.draw < 0) {
                ++empty;
                EXPECT_TRUE(std::isinf(depth[i]) && depth[i] > 0) << x << "," << y;
                EXPECT_EQ(clip[i], 0.0f);
                EXPECT_EQ(node[i], CANDELA_NO_ID);
                EXPECT_EQ(material[i], CANDELA_NO_ID);
                EXPECT_EQ(normal[3 * i] * normal[3 * i] + normal[3 * i + 1] * normal[3 * i + 1], 0.0f);
                continue;
            }
            // Pixel centres within a hundredth of a triangle's edge may fall to either neighbour.
            if (hit.edge < 1e-2 && hit.draw == 1) continue;
            const glm::dvec3 p = origin + hit.t * direction;
            const double expected = -(worldToView * glm::dvec4(p, 1.0)).z;
            const double error = std::abs(depth[i] - expected) / expected;
            const glm::dvec3 n(normal[3 * i], normal[3 * i + 1], normal[3 * i + 2]);
            ASSERT_EQ(node[i], hit.draw == 0 ? 7u : 3u) << x << "," << y;
            EXPECT_EQ(mesh[i], hit.draw == 0 ? 2u : 5u);
            EXPECT_EQ(primitive[i], hit.draw == 0 ? 0u : 1u);
            EXPECT_EQ(material[i], uint32_t(hit.draw));
            EXPECT_EQ(instance[i], CANDELA_NO_ID);
            normalError = std::max(normalError, glm::length(n - hit.normal));
            // The depth buffer holds znear / depth (reverse Z, no far plane).
            clipError = std::max(clipError, std::abs(double(clip[i]) * expected / view.znear - 1.0));
            if (hit.draw == 0) {
                ++plane;
                planeError = std::max(planeError, error);
            } else {
                ++sphere;
                sphereError = std::max(sphereError, error);
                // The analytic sphere: the nearest root of |o + t·d − c| = r.
                const glm::dvec3 oc = origin - kSphereCentre;
                const double b = glm::dot(oc, direction), c = glm::dot(oc, oc) - kSphereRadius * kSphereRadius;
                const double t = -b - std::sqrt(b * b - c);
                const glm::dvec3 q = origin + t * direction, trueNormal = (q - kSphereCentre) / kSphereRadius;
                // Away from the silhouette (the tessellation's error grows as 1 / cos there): the
                // distance along the normal between the true sphere and its triangles.
                const double facing = -glm::dot(trueNormal, direction);
                if (facing > 0.5) {
                    sphereAnalytic = std::max(sphereAnalytic, std::abs(depth[i] + (worldToView * glm::dvec4(q, 1.0)).z) /
                                                                  glm::length(worldToView * glm::dvec4(direction, 0.0)) * facing);
                    analyticNormal = std::max(analyticNormal, glm::length(n - trueNormal));
                }
            }
        }
    std::printf("aov: %u plane, %u sphere, %u empty pixels (%u within %.3g px of a silhouette left out); depth relative error: plane %.2g, sphere's triangles %.2g; distance to "
                "the analytic sphere %.2g m; normal error %.2g (analytic %.2g); clip depth %.2g\n",
                plane, sphere, empty, silhouette, snap, planeError, sphereError, sphereAnalytic, normalError, analyticNormal, clipError);
    EXPECT_GT(plane, 3000u);
    EXPECT_GT(sphere, 1500u);
    EXPECT_GT(empty, 100u);
    // Float precision: the interpolated world position of the snapped triangle, 24-bit mantissas.
    EXPECT_LT(planeError, 2e-5);
    EXPECT_LT(sphereError, 2e-5);
    // The tessellation: the triangles of a 48 × 96 sphere of radius 0.5 (steps of π/48 in both
    // angles) lie within 0.5 · 2 · (π/48)² / 8 = 5.35e-4 of it (at a quad's centre, on the equator);
    // their interpolated normals within 1% of its.
    EXPECT_LT(sphereAnalytic, 5.5e-4);
    EXPECT_LT(normalError, 1e-4);
    EXPECT_LT(analyticNormal, 1e-2);
    EXPECT_LT(clipError, 2e-5);
}

// Every pixel the aov pass covers is one the image covers (alpha > 0 over a transparent
// background), on both shading paths at MSAA 1, and every output is the same on both.
TEST_F(AovTest, CoverageIsTheImagesAndBothPathsAgreeAtMsaa1) {
    if (!context().choices().visibilityUnsupported.empty()) GTEST_SKIP() << context().choices().visibilityUnsupported;
    const scene::Scene grid = assets::makeSphereGrid();
    options::PixelOutputs all;
    for (const auto& [output, name] : options::kPixelOutputNames) all.add(output);
    const CapturedFrame forward = render(grid, all, options::ShadingPath::Forward);
    const CapturedFrame visibility = render(grid, all, options::ShadingPath::Visibility);
    ASSERT_EQ(renderer().lastVisibility() != nullptr, true);
    for (const CapturedFrame* frame : {&forward, &visibility}) {
        const auto& depth = valuesOf<float>(*frame, PixelOutput::Depth);
        uint32_t covered = 0;
        for (size_t i = 0; i < depth.size(); ++i) {
            ASSERT_EQ(std::isfinite(depth[i]), frame->rgba8[4 * i + 3] > 0) << "pixel " << i;
            covered += std::isfinite(depth[i]);
        }
        // (The grid spans 80% of the image's height since framing fits its silhouette: 22.5% of the
        // pixels; 91% of the height and over a quarter of them before.)
        EXPECT_GT(covered, depth.size() / 5);
    }
    ASSERT_EQ(forward.outputs.size(), visibility.outputs.size());
    for (size_t o = 0; o < forward.outputs.size(); ++o) {
        EXPECT_EQ(forward.outputs[o].floats, visibility.outputs[o].floats) << options::pixelOutputName(forward.outputs[o].output);
        EXPECT_EQ(forward.outputs[o].ids, visibility.outputs[o].ids) << options::pixelOutputName(forward.outputs[o].output);
    }
}

// Without outputs besides colour the frame has no aov pass and --explain says why; with colour
// left out the passes that make the image are culled.
TEST_F(AovTest, CostsNothingUnlessAskedForAndColourIsCulledWhenLeftOut) {
    const scene::Scene grid = assets::makeSphereGrid();
    const CapturedFrame color = render(grid, {PixelOutput::Color});
    EXPECT_FALSE(declares("aov"));
    EXPECT_TRUE(color.outputs.empty());
    const std::vector<std::string> lines = renderer().explain();
    EXPECT_NE(std::find_if(lines.begin(), lines.end(), [](const std::string& l) { return l.rfind("left out: pass 'aov'", 0) == 0; }), lines.end());
    const CapturedFrame depthOnly = render(grid, {PixelOutput::Depth});
    EXPECT_TRUE(depthOnly.rgba8.empty());
    ASSERT_EQ(depthOnly.outputs.size(), 1u);
    const graph::RenderGraph& graph = renderer().lastGraph();
    EXPECT_NE(graph.compiled().passes[*graph.findPass("forward")].cullReason, graph::CullReason::None);
    EXPECT_EQ(graph.compiled().passes[*graph.findPass("aov")].cullReason, graph::CullReason::None);
    // At MSAA 4 the outputs are the single-sample ones: identical to MSAA 1's.
    const CapturedFrame msaa = render(grid, {PixelOutput::Depth}, options::ShadingPath::Forward, 4);
    EXPECT_EQ(msaa.outputs[0].floats, depthOnly.outputs[0].floats);
}

#ifdef CANDELA_SHARED_ASSETS
// IDs against the draw list: each covered pixel's (node, mesh, primitive, material) is a drawn
// draw's; a node whose draws are hidden never appears; instanced draws give their instances.
TEST_F(AovTest, IdsAreThoseOfTheDrawsDrawnThere) {
    const std::filesystem::path models = sharedAssets() / "models";
    if (!std::filesystem::is_directory(models)) GTEST_SKIP() << "../shared/assets not present";
    scene::Scene truck = assets::loadGltf(models / "CesiumMilkTruck/glTF-Binary/CesiumMilkTruck.glb");
    const options::PixelOutputs ids{PixelOutput::NodeId, PixelOutput::MeshId, PixelOutput::PrimitiveId, PixelOutput::MaterialId};
    const auto tuples = [&](const CapturedFrame& frame) {
        std::set<std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>> seen;
        const auto& n = valuesOf<uint32_t>(frame, PixelOutput::NodeId);
        const auto& m = valuesOf<uint32_t>(frame, PixelOutput::MeshId);
        const auto& p = valuesOf<uint32_t>(frame, PixelOutput::PrimitiveId);
        const auto& mat = valuesOf<uint32_t>(frame, PixelOutput::MaterialId);
        for (size_t i = 0; i < n.size(); ++i)
            if (n[i] != CANDELA_NO_ID) seen.insert({n[i], m[i], p[i], mat[i]});
        return seen;
    };
    const auto drawn = [&](const scene::Scene& s) {
        std::set<std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>> out;
        for (const scene::Draw& d : s.draws)
            if (!d.hidden) out.insert({uint32_t(s.nodes[size_t(d.node)].source), uint32_t(d.mesh), uint32_t(d.primitive), d.material});
        return out;
    };
    const auto before = tuples(render(truck, ids));
    ASSERT_GE(before.size(), 3u);
    for (const auto& t : before) EXPECT_TRUE(drawn(truck).contains(t));
    // Hide the node of the first tuple seen (as KHR_node_visibility would): it is gone, the rest stay.
    const uint32_t hidden = std::get<0>(*before.begin());
    for (scene::Draw& d : truck.draws)
        if (uint32_t(truck.nodes[size_t(d.node)].source) == hidden) d.hidden = true;
    renderer().sceneReplaced();
    const auto after = tuples(render(truck, ids));
    for (const auto& t : after) {
        EXPECT_NE(std::get<0>(t), hidden);
        EXPECT_TRUE(drawn(truck).contains(t));
    }
    // Hiding a node can only uncover what was behind it: everything else seen before is still seen.
    for (const auto& t : before)
        if (std::get<0>(t) != hidden) {
            EXPECT_TRUE(after.contains(t));
        }

    const scene::Scene instanced = assets::loadGltf(models / "SimpleInstancing/glTF-Binary/SimpleInstancing.glb");
    const CapturedFrame frame = render(instanced, {PixelOutput::InstanceId, PixelOutput::NodeId});
    std::set<uint32_t> instances;
    for (uint32_t id : valuesOf<uint32_t>(frame, PixelOutput::InstanceId))
        if (id != CANDELA_NO_ID) instances.insert(id);
    ASSERT_FALSE(instanced.instanceIndices.empty());
    EXPECT_GT(instances.size(), instanced.instanceIndices.size() / 2);
    for (uint32_t id : instances) EXPECT_LT(id, instanced.instanceIndices.size());
}
#endif

}  // namespace
}  // namespace candela::test::aov_test
