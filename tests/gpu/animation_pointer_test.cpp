// KHR_animation_pointer and KHR_node_visibility on the GPU (lavapipe, validation with
// synchronization checks on), through both shading paths: an animated material factor draws, at
// each time, exactly the image of a static scene with that factor (its per-frame material buffers
// standing in for the scene's); a hidden node draws nothing and its light lights nothing — exactly
// the image of the scene without them —, and an animated visibility shows both at its key.
// Metric everywhere: byte-identical 8-bit frames.
#include "gpu_test.h"
#include "shading_summary_util.h"

#include "animation_pointer_util.h"
#include "assets/builtin_scenes.h"
#include "render/renderer.h"
#include "scene/animated_properties.h"

#include <algorithm>

namespace candela::test::animation_pointer_test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 120;
using assets::test::GltfBuilder;
using assets::test::Json;

size_t differingPixels(const CapturedFrame& a, const CapturedFrame& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.rgba8.size(); i += 4)
        n += !std::equal(a.rgba8.begin() + std::ptrdiff_t(i), a.rgba8.begin() + std::ptrdiff_t(i + 4), b.rgba8.begin() + std::ptrdiff_t(i));
    return n;
}

class AnimationPointerTest : public GpuTest {
protected:
    static RenderSettings settings(const scene::Scene& scene, const pose::ScenePose* pose, options::ShadingPath path) {
        RenderSettings s{.width = kWidth, .height = kHeight, .scene = &scene, .pose = pose};
        s.shadingPath = path;
        return s;
    }
    static bool declares(const Renderer& renderer, const char* resource) {
        const auto& resources = renderer.lastGraph().declaration().resources;
        return std::any_of(resources.begin(), resources.end(), [&](const graph::ResourceDecl& r) { return r.name == resource; });
    }

    // The sphere grid with material `material`'s `pointer` field animated from `from` to `to`
    // over one second, against the same grid with the pose's value baked in, at 0, ½ and 1 s, on
    // both paths; the frames at 0 and 1 s differ; the animated frames upload `buffer`.
    void expectPosedMaterialMatchesStatic(const char* pointer, std::vector<float> from, const std::vector<float>& to,
                                          const char* buffer) {
        const uint32_t material = 24;  // the middle sphere
        scene::Scene grid = assets::makeSphereGrid();
        const uint16_t field = scene::parsePointer(pointer)->field;
        grid.materials[material].animatedLayers = scene::layersAnimationMayNeed(grid.materials[material], std::vector{field});
        animation::Animation animation{.name = "tint", .duration = 1.0};
        const uint32_t width = uint32_t(from.size());
        from.insert(from.end(), to.begin(), to.end());
        animation.samplers.push_back({.times = {0, 1}, .values = from, .width = width});
        animation.properties.push_back({.sampler = 0, .object = uint8_t(scene::AnimatedObject::Material), .index = material, .field = field});
        grid.animations.push_back(animation);
        pose::ScenePose pose(grid, {0});
        scene::Scene frozen = grid;
        frozen.animations.clear();
        for (options::ShadingPath path : shadingPaths()) {
            Renderer animated(context()), still(context());
            std::vector<CapturedFrame> frames;
            for (double t : {0.0, 0.5, 1.0}) {
                pose.evaluate(t, /*loop=*/false);
                frames.push_back(animated.capture(settings(grid, &pose, path)));
                EXPECT_TRUE(declares(animated, buffer)) << buffer;
                EXPECT_FALSE(declares(animated, "posed_draws"));  // no node moves
                EXPECT_EQ(animated.lastPosed(), (PosedSummary{.materials = 1, .materialLayers = std::string(buffer) == "posed_material_layers"}));
                EXPECT_EQ(animated.lastPlan()->path, path);
                frozen.materials[material] = pose.materials()[material];
                still.sceneReplaced();
                EXPECT_EQ(differingPixels(frames.back(), still.capture(settings(frozen, nullptr, path))), 0u)
                    << pointer << " at " << t << " s, path " << int(path);
            }
            // The middle sphere covers about 60 pixels of the frame (measured: 52 differ).
            EXPECT_GT(differingPixels(frames.front(), frames.back()), size_t(30)) << pointer;
        }
    }
};

TEST_F(AnimationPointerTest, AnimatedBaseColorDrawsTheStaticImageOfEachTimeOnBothPaths) {
    expectPosedMaterialMatchesStatic("/materials/0/pbrMetallicRoughness/baseColorFactor", {1, 0, 0, 1}, {0, 0, 1, 1},
                                     "posed_materials");
}

// A layer factor animated from 0: the layered variant and the layer buffer exist from the start,
// and the per-frame layer data reaches both paths.
TEST_F(AnimationPointerTest, ClearcoatAnimatedFromZeroDrawsTheStaticImageOfEachTimeOnBothPaths) {
    expectPosedMaterialMatchesStatic("/materials/0/extensions/KHR_materials_clearcoat/clearcoatFactor", {0}, {1},
                                     "posed_material_layers");
}

// A floor lit by a lamp; node 2 (a triangle over the floor with a second lamp under it) hidden,
// optionally shown from 1 s by an animation. Both lamps are point lights, so that the light types
// (a variant bit) are the same with or without the hidden one.
scene::Scene visibilityScene(const std::filesystem::path& dir, bool withHiddenNode, bool animated) {
    GltfBuilder b;
    const int pos = b.addFloats({-2, 0, -2, 2, 0, -2, 2, 0, 2, -2, 0, 2}, "VEC3", 3);
    const int normal = b.addFloats({0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0}, "VEC3", 3);
    b.doc["materials"] = Json::array({{{"doubleSided", true}, {"pbrMetallicRoughness", {{"metallicFactor", 0}}}}});
    const int floor = b.addMesh({{"POSITION", pos}, {"NORMAL", normal}}, b.addIndices({0, 2, 1, 0, 3, 2}), 0);  // counter-clockwise from above
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] =
        Json::array({{{"type", "point"}, {"intensity", 6}}, {{"type", "point"}, {"intensity", 4}, {"color", {1, 0.2, 0.1}}}});
    assets::test::useExtension(b, "KHR_lights_punctual");
    std::vector<int> roots = {b.addNode({{"mesh", floor}}),
                              b.addNode({{"translation", {-1, 1.5, -1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}})};
    if (withHiddenNode) {
        const int tri = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
        const int triNormal = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
        const int triangle = b.addMesh({{"POSITION", tri}, {"NORMAL", triNormal}}, b.addIndices({0, 1, 2}), 0);
        const int lamp = b.addNode({{"translation", {0, -0.4, 0.2}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
        const int hidden = b.addNode({{"mesh", triangle}, {"translation", {0.3, 0.6, 0.5}}, {"children", {lamp}}});
        assets::test::setVisible(b, hidden, false);
        roots.push_back(hidden);
        if (animated)
            assets::test::addPointerAnimation(b, {{.pointer = "/nodes/" + std::to_string(hidden) + "/extensions/KHR_node_visibility/visible",
                                                  .times = {0, 1}, .values = {0, 1}, .interpolation = "STEP",
                                                  .componentType = assets::test::kUnsignedByte}});
    }
    b.setScene(roots);
    return assets::loadGltf(b.writeGltf(dir, withHiddenNode ? (animated ? "animated" : "hidden") : "without"));
}

TEST_F(AnimationPointerTest, AHiddenNodeDrawsNothingAndItsLightLightsNothingOnBothPaths) {
    TempDir dir;
    const scene::Scene hidden = visibilityScene(dir.path(), true, false);
    const scene::Scene without = visibilityScene(dir.path(), false, false);
    ASSERT_EQ(hidden.lights.size(), 2u);
    ASSERT_TRUE(hidden.lights[1].hidden);
    // Shown: the same file with the node visible (what the animation shows from 1 s).
    scene::Scene shown = hidden;
    for (scene::Draw& d : shown.draws) d.hidden = false;
    for (scene::Light& l : shown.lights) l.hidden = false;
    scene::Scene animatedScene = visibilityScene(dir.path(), true, true);
    pose::ScenePose pose(animatedScene, {0});
    for (options::ShadingPath path : shadingPaths()) {
        const auto fixedView = [&](RenderSettings s) {
            // Framing would follow the bounds, which differ between the scenes.
            s.camera.orbit = glm::vec3(20.0f, 55.0f, 5.0f);
            s.camera.target = glm::vec3(0.0f);
            return s;
        };
        Renderer a(context()), b(context()), c(context()), d(context());
        const CapturedFrame withoutFrame = a.capture(fixedView(settings(without, nullptr, path)));
        const CapturedFrame hiddenFrame = b.capture(fixedView(settings(hidden, nullptr, path)));
        EXPECT_EQ(hiddenFrame.rgba8, withoutFrame.rgba8) << "path " << int(path);
        EXPECT_EQ(lastShading(b).hiddenDraws, 1u);
        EXPECT_FALSE(lastShading(b).posed);
        const CapturedFrame shownFrame = c.capture(fixedView(settings(shown, nullptr, path)));
        // The triangle and the lamp's light on the floor (measured: 598 pixels, 3% of the frame).
        EXPECT_GT(differingPixels(shownFrame, withoutFrame), size_t(kWidth * kHeight / 100));
        // Animated: hidden before the key (posed draws and lights), shown after it.
        pose.evaluate(0.5, false);
        EXPECT_EQ(d.capture(fixedView(settings(animatedScene, &pose, path))).rgba8, withoutFrame.rgba8) << "path " << int(path);
        EXPECT_TRUE(declares(d, "posed_draws"));
        EXPECT_TRUE(declares(d, "posed_lights"));
        pose.evaluate(1.5, false);
        EXPECT_EQ(d.capture(fixedView(settings(animatedScene, &pose, path))).rgba8, shownFrame.rgba8) << "path " << int(path);
    }
}

}  // namespace
}  // namespace candela::test::animation_pointer_test
