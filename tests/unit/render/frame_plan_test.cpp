// The frame plan (render/frame_plan.h): each decision of a scene frame from its facts, checked by
// the plan's fields; and the --explain lines the plan gives (render/explain_plan.h).
#include "render/explain_plan.h"
#include "render/frame_plan.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace candela {
namespace {

using options::DebugView;
using options::ShadingPath;

// A frame the visibility path can take: asked for, a capable device, an environment behind it.
FrameFacts visibilityFrame() {
    return {.requestedPath = ShadingPath::Visibility, .environment = true, .devicePath = ShadingPath::Forward,
            .devicePathReason = "the device's default: forward here"};
}

TEST(FramePlan, TakesThePathAskedForWhenItCan) {
    EXPECT_EQ(planFrame(visibilityFrame()).path, ShadingPath::Visibility);
    EXPECT_EQ(planFrame(visibilityFrame()).pathReason, PathReason::Requested);
    FrameFacts forward = visibilityFrame();
    forward.requestedPath = ShadingPath::Forward;
    EXPECT_EQ(planFrame(forward).path, ShadingPath::Forward);
    EXPECT_EQ(planFrame(forward).pathReason, PathReason::Requested);
    // Asked for forward, a frame says no other reason.
    forward.visibilityUnsupported = "no 64-bit atomics";
    forward.groundTruth = true;
    EXPECT_EQ(planFrame(forward).pathReason, PathReason::Requested);
    EXPECT_EQ(explainForwardPath(planFrame(forward), forward), "shading path: forward");
}

TEST(FramePlan, AutoTakesTheDevicesDefault) {
    FrameFacts facts = visibilityFrame();
    facts.requestedPath = ShadingPath::Auto;
    EXPECT_EQ(planFrame(facts).path, ShadingPath::Forward);
    EXPECT_EQ(planFrame(facts).pathReason, PathReason::DeviceDefault);
    EXPECT_EQ(explainForwardPath(planFrame(facts), facts), "shading path: forward (the device's default: forward here)");
    facts.devicePath = ShadingPath::Visibility;
    EXPECT_EQ(planFrame(facts).path, ShadingPath::Visibility);
}

TEST(FramePlan, FallsBackToForwardWithTheFirstReason) {
    struct Case {
        void (*change)(FrameFacts&);
        PathReason reason;
    };
    const Case cases[] = {
        {[](FrameFacts& f) { f.visibilityUnsupported = "no 64-bit atomics"; }, PathReason::Unsupported},
        {[](FrameFacts& f) { f.groundTruth = true; }, PathReason::GroundTruth},
        {[](FrameFacts& f) { f.samples = 4, f.integerMsaaSampling = false; }, PathReason::IntegerMsaaSampling},
        {[](FrameFacts& f) { f.shadingListsFit = false; }, PathReason::TooManyShadingLists},
    };
    for (const Case& c : cases) {
        FrameFacts facts = visibilityFrame();
        c.change(facts);
        const FramePlan plan = planFrame(facts);
        EXPECT_EQ(plan.path, ShadingPath::Forward);
        EXPECT_EQ(plan.pathReason, c.reason);
    }
    // With several, the first of the table above: each case with every later one.
    for (size_t first = 0; first < std::size(cases); ++first) {
        FrameFacts facts = visibilityFrame();
        for (size_t c = first; c < std::size(cases); ++c) cases[c].change(facts);
        EXPECT_EQ(planFrame(facts).pathReason, cases[first].reason) << first;
    }
    FrameFacts both = visibilityFrame();
    both.visibilityUnsupported = "no 64-bit atomics";
    both.groundTruth = true;
    EXPECT_EQ(explainForwardPath(planFrame(both), both), "shading path: forward (no 64-bit atomics)");
    FrameFacts lists = visibilityFrame();
    lists.shadingListsFit = false;
    EXPECT_EQ(explainForwardPath(planFrame(lists), lists),
              "shading path: forward (the frame needs more than 1024 shading lists, the visibility path's limit)");
    // One sample needs no multisampled integer image.
    FrameFacts single = visibilityFrame();
    single.integerMsaaSampling = false;
    EXPECT_EQ(planFrame(single).path, ShadingPath::Visibility);
}

TEST(FramePlan, SkyGoesToTheTonemapUnlessTransmissionOrTheOutputNeedsIt) {
    FrameFacts facts = visibilityFrame();
    EXPECT_EQ(planFrame(facts).sky, SkyPlacement::Tonemap);
    facts.transmissiveDraws = true;  // they see the sky through them
    EXPECT_EQ(planFrame(facts).sky, SkyPlacement::SkyboxPass);
    facts.transmissionBackgroundDisabled = true;  // they do not see the opaque image: the tonemap's sky is enough
    EXPECT_EQ(planFrame(facts).sky, SkyPlacement::Tonemap);
    FrameFacts hdr = visibilityFrame();
    hdr.floatOutput = true;  // the HDR image is the output: the sky must be in it
    EXPECT_EQ(planFrame(hdr).sky, SkyPlacement::SkyboxPass);
    FrameFacts off = visibilityFrame();
    off.skyboxDisabled = true;  // declared, to be switched off
    EXPECT_EQ(planFrame(off).sky, SkyPlacement::SkyboxPass);
}

TEST(FramePlan, TheTonemapsSkyIsDepthTestedAtOneSampleWithoutTransmissiveDraws) {
    FrameFacts facts = visibilityFrame();
    facts.samples = 1;
    EXPECT_TRUE(planFrame(facts).skyWhereUncovered);
    EXPECT_TRUE(planFrame(facts).skyOverClearImage);
    EXPECT_EQ(explainPasses(planFrame(facts), facts, false).back(),
              "sky: composited by the tonemap where nothing was drawn (depth-tested, the image not read there: no "
              "blended draws; no skybox pass)");
    FrameFacts finite = facts;
    finite.farPlaneAtInfinity = false;  // geometry at the far plane has its depth 0: the image is read
    EXPECT_TRUE(planFrame(finite).skyWhereUncovered);
    EXPECT_FALSE(planFrame(finite).skyOverClearImage);
    FrameFacts blended = facts;
    blended.blendedDraws = true;  // they leave the depth as it was, not the image: it is read
    EXPECT_TRUE(planFrame(blended).skyWhereUncovered);
    EXPECT_FALSE(planFrame(blended).skyOverClearImage);
    EXPECT_EQ(explainPasses(planFrame(blended), blended, false).back(),
              "sky: composited by the tonemap where nothing was drawn (depth-tested; no skybox pass)");
    FrameFacts msaa = facts;
    msaa.samples = 4;  // the depth is multisampled, the image the tonemap reads is not
    EXPECT_FALSE(planFrame(msaa).skyWhereUncovered);
    EXPECT_FALSE(planFrame(msaa).skyOverClearImage);
    EXPECT_EQ(explainPasses(planFrame(msaa), msaa, false).back(), "sky: composited under the image by the tonemap (no skybox pass)");
    FrameFacts blind = facts;
    blind.transmissiveDraws = blind.transmissionBackgroundDisabled = true;  // they write depth and may be seen through
    EXPECT_EQ(planFrame(blind).sky, SkyPlacement::Tonemap);
    EXPECT_FALSE(planFrame(blind).skyWhereUncovered);
    FrameFacts hdr = facts;
    hdr.floatOutput = true;  // the skybox pass draws it, depth-tested itself
    EXPECT_FALSE(planFrame(hdr).skyWhereUncovered);
}

TEST(FramePlan, SkyboxLeftOutWithItsReason) {
    FrameFacts facts = visibilityFrame();
    facts.skyboxWanted = false;
    FramePlan plan = planFrame(facts);
    EXPECT_EQ(plan.sky, SkyPlacement::None);
    EXPECT_EQ(1, std::count(plan.leftOut.begin(), plan.leftOut.end(), LeftOut{PlannedPart::Skybox, LeftOutReason::NotTheBackground}));
    facts.skyboxWanted = true;
    facts.debugView = DebugView::BaseColor;
    plan = planFrame(facts);
    EXPECT_EQ(plan.sky, SkyPlacement::None);
    EXPECT_EQ(1, std::count(plan.leftOut.begin(), plan.leftOut.end(), LeftOut{PlannedPart::Skybox, LeftOutReason::DebugView}));
    // Without an environment there is no sky, and none to leave out.
    facts.environment = false;
    EXPECT_FALSE(planFrame(facts).leavesOut(PlannedPart::Skybox));
    facts.debugView = DebugView::None;
    EXPECT_EQ(planFrame(facts).sky, SkyPlacement::None);
    EXPECT_FALSE(planFrame(facts).leavesOut(PlannedPart::Skybox));
}

TEST(FramePlan, TransmissionSeesTheOpaqueImageUnlessItsBackgroundIsDisabled) {
    FrameFacts facts = visibilityFrame();
    EXPECT_EQ(planFrame(facts).transmission, TransmissionPlan::None);
    const FramePlan none = planFrame(facts);
    EXPECT_EQ(1, std::count(none.leftOut.begin(), none.leftOut.end(),
                            LeftOut{PlannedPart::TransmissionBackground, LeftOutReason::NoTransmissive}));
    facts.transmissiveDraws = true;
    EXPECT_EQ(planFrame(facts).transmission, TransmissionPlan::SeesOpaqueImage);
    EXPECT_FALSE(planFrame(facts).leavesOut(PlannedPart::TransmissionBackground));
    facts.transmissionBackgroundDisabled = true;
    EXPECT_EQ(planFrame(facts).transmission, TransmissionPlan::Blind);
    FrameFacts debug = visibilityFrame();
    debug.debugView = DebugView::BaseColor;  // the draw list then has no transmissive range
    const FramePlan plan = planFrame(debug);
    EXPECT_EQ(1, std::count(plan.leftOut.begin(), plan.leftOut.end(),
                           LeftOut{PlannedPart::TransmissionBackground, LeftOutReason::DebugView}));
}

TEST(FramePlan, VisibilityPathExpandsAndDrawsBlendedDrawsOnlyWhenNeeded) {
    FrameFacts facts = visibilityFrame();
    facts.samples = 4;
    EXPECT_FALSE(planFrame(facts).msaaExpand);
    EXPECT_FALSE(planFrame(facts).blendedPass);
    facts.blendedDraws = true;
    EXPECT_TRUE(planFrame(facts).msaaExpand);
    EXPECT_TRUE(planFrame(facts).blendedPass);
    facts.transmissiveDraws = true;  // forward_transmission draws the blended ones too
    EXPECT_TRUE(planFrame(facts).msaaExpand);
    EXPECT_FALSE(planFrame(facts).blendedPass);
    facts.samples = 1;
    EXPECT_FALSE(planFrame(facts).msaaExpand);
    // The forward path draws its own blended draws and needs no expansion.
    facts.requestedPath = ShadingPath::Forward;
    facts.samples = 4;
    EXPECT_FALSE(planFrame(facts).msaaExpand);
    EXPECT_FALSE(planFrame(facts).blendedPass);
}

TEST(FramePlan, VisibilityPathDrawsPointsAndLinesForwardAfterIt) {
    FrameFacts facts = visibilityFrame();
    facts.pointAndLineDraws = true;
    EXPECT_TRUE(planFrame(facts).pointsAndLinesPass);
    EXPECT_FALSE(planFrame(facts).msaaExpand);
    facts.samples = 4;  // drawn into the multisampled image, like blended draws
    EXPECT_TRUE(planFrame(facts).msaaExpand);
    EXPECT_FALSE(planFrame(facts).blendedPass);
    // The forward path draws them in its forward pass.
    facts.requestedPath = ShadingPath::Forward;
    EXPECT_FALSE(planFrame(facts).pointsAndLinesPass);
    EXPECT_FALSE(planFrame(facts).msaaExpand);
}

TEST(FramePlan, SkinMorphAsThePoseNeedsIt) {
    FrameFacts facts = visibilityFrame();
    EXPECT_EQ(planFrame(facts).deform, DeformPlan::Static);
    EXPECT_FALSE(planFrame(facts).leavesOut(PlannedPart::SkinMorph));
    facts.deformable = true;
    EXPECT_EQ(planFrame(facts).deform, DeformPlan::NoneInPose);
    EXPECT_TRUE(planFrame(facts).leavesOut(PlannedPart::SkinMorph));
    facts.deformedDraws = 3;
    EXPECT_EQ(planFrame(facts).deform, DeformPlan::Deformed);
    EXPECT_FALSE(planFrame(facts).leavesOut(PlannedPart::SkinMorph));
    EXPECT_FALSE(planFrame(facts).leavesOut(PlannedPart::DeformedDraws));
    facts.skinMorphDisabled = true;
    const FramePlan plan = planFrame(facts);
    EXPECT_FALSE(plan.leavesOut(PlannedPart::SkinMorph));
    EXPECT_EQ(plan.deform, DeformPlan::Disabled);
    EXPECT_EQ(explainLeftOut(plan, facts, {PlannedPart::DeformedDraws}),
              std::vector<std::string>{"left out: the 3 deformed draws (skin_morph disabled: nothing places their vertices)"});
}

TEST(FramePlan, SkinMorphDisabledWithNothingDeformedSaysNothingIsDeformed) {
    FrameFacts facts = visibilityFrame();
    facts.deformable = true;
    facts.skinMorphDisabled = true;
    const FramePlan plan = planFrame(facts);
    EXPECT_EQ(plan.deform, DeformPlan::NoneInPose);
    EXPECT_TRUE(plan.leavesOut(PlannedPart::SkinMorph));
    EXPECT_FALSE(plan.leavesOut(PlannedPart::DeformedDraws));
}

// The plan's first step (planDrawList), taken before the draw list exists: it leaves the deformed
// draws out of the list only when skin_morph is off and the pose deforms some, draws transmissive
// draws with the rest in a debug view, and decides skin_morph as planFrame does.
TEST(DrawListPlan, HidesTheDeformedDrawsOnlyWhenSkinMorphIsOffAndThePoseDeformsSome) {
    FrameFacts facts = visibilityFrame();
    facts.skinMorphDisabled = true;
    EXPECT_FALSE(planDrawList(facts).hidesDeformedDraws()) << "a static scene";
    facts.deformable = true;
    EXPECT_FALSE(planDrawList(facts).hidesDeformedDraws()) << "nothing deformed in this pose";
    facts.deformedDraws = 2;
    EXPECT_TRUE(planDrawList(facts).hidesDeformedDraws());
    facts.skinMorphDisabled = false;
    EXPECT_FALSE(planDrawList(facts).hidesDeformedDraws());
}

TEST(DrawListPlan, ADebugViewDrawsTransmissiveDrawsWithTheRest) {
    FrameFacts facts = visibilityFrame();
    EXPECT_TRUE(planDrawList(facts).transmissionRange);
    facts.debugView = DebugView::BaseColor;
    EXPECT_FALSE(planDrawList(facts).transmissionRange);
}

TEST(DrawListPlan, DecidesSkinMorphAsTheFramePlanDoes) {
    for (const bool deformable : {false, true})
        for (const uint32_t deformed : {0u, 3u})
            for (const bool disabled : {false, true}) {
                FrameFacts facts = visibilityFrame();
                facts.deformable = deformable;
                facts.deformedDraws = deformable ? deformed : 0u;
                facts.skinMorphDisabled = disabled;
                EXPECT_EQ(planDrawList(facts).deform, planFrame(facts).deform) << deformable << deformed << disabled;
            }
}

TEST(FramePlan, TooManyShadingListsChangesOnlyThePath) {
    // FrameBuilder plans again when the visibility tables do not fit: only the path's fields may move.
    FrameFacts facts = visibilityFrame();
    facts.samples = 4;
    facts.blendedDraws = true;
    facts.deformable = true;
    facts.deformedDraws = 2;
    facts.sheen = true;
    facts.pointAndLineDraws = true;
    FramePlan fits = planFrame(facts);
    facts.shadingListsFit = false;
    const FramePlan fallback = planFrame(facts);
    EXPECT_EQ(fallback.path, ShadingPath::Forward);
    EXPECT_EQ(fallback.pathReason, PathReason::TooManyShadingLists);
    EXPECT_TRUE(fits.msaaExpand && fits.blendedPass && fits.pointsAndLinesPass);
    EXPECT_FALSE(fallback.msaaExpand || fallback.blendedPass || fallback.pointsAndLinesPass);
    fits.path = fallback.path;
    fits.pathReason = fallback.pathReason;
    fits.msaaExpand = fallback.msaaExpand;
    fits.blendedPass = fallback.blendedPass;
    fits.pointsAndLinesPass = fallback.pointsAndLinesPass;
    EXPECT_EQ(fits, fallback);
}

TEST(FramePlan, SheenLutOnlyForSheen) {
    FrameFacts facts = visibilityFrame();
    EXPECT_FALSE(planFrame(facts).sheenLut);
    EXPECT_TRUE(planFrame(facts).leavesOut(PlannedPart::SheenLut));
    facts.sheen = true;
    EXPECT_TRUE(planFrame(facts).sheenLut);
    EXPECT_FALSE(planFrame(facts).leavesOut(PlannedPart::SheenLut));
}

TEST(FramePlan, ADebugViewOfDataIsShownAsItIsAndOfLightAsSet) {
    FrameFacts facts = visibilityFrame();
    EXPECT_EQ(planFrame(facts).tonemapLook, TonemapLook::AsSet);
    facts.debugView = DebugView::Roughness;
    EXPECT_EQ(planFrame(facts).tonemapLook, TonemapLook::DataAsIs);
    facts.debugView = DebugView::Specular;
    EXPECT_EQ(planFrame(facts).tonemapLook, TonemapLook::AsSet);
}

TEST(FramePlan, ADebugViewPutsGreyWhereTheSkyWasTheBackground) {
    FrameFacts facts = visibilityFrame();
    facts.skyboxWanted = true;
    EXPECT_FALSE(planFrame(facts).greyBackground);  // no debug view: the sky
    facts.debugView = DebugView::BaseColor;
    EXPECT_TRUE(planFrame(facts).greyBackground);
    EXPECT_EQ(planFrame(facts).sky, SkyPlacement::None);
    FrameFacts coloured = facts;
    coloured.backgroundColour = true;  // the colour given stays
    EXPECT_FALSE(planFrame(coloured).greyBackground);
    FrameFacts noSkybox = facts;
    noSkybox.skyboxWanted = false;     // the background was transparent or a colour already
    EXPECT_FALSE(planFrame(noSkybox).greyBackground);
    FrameFacts noEnvironment = facts;
    noEnvironment.environment = false;
    EXPECT_FALSE(planFrame(noEnvironment).greyBackground);
}

TEST(FramePlan, AlphaMaskedDrawsUseCoverageAtMsaaWhereTheDeviceStoresAlphaOne) {
    FrameFacts facts = visibilityFrame();
    facts.alphaToOne = true;
    EXPECT_EQ(planFrame(facts).alphaMasking, AlphaMasking::AlphaTest);  // one sample
    EXPECT_EQ(explainAlphaMasking(planFrame(facts).alphaMasking), "");
    facts.samples = 4;
    EXPECT_EQ(planFrame(facts).alphaMasking, AlphaMasking::AlphaToCoverage);
    EXPECT_EQ(explainAlphaMasking(planFrame(facts).alphaMasking), "; alpha-masked materials use alpha to coverage");
    facts.alphaToOne = false;
    EXPECT_EQ(planFrame(facts).alphaMasking, AlphaMasking::AlphaTestNoAlphaToOne);
    EXPECT_EQ(explainAlphaMasking(planFrame(facts).alphaMasking),
              "; alpha-masked materials keep the alpha test (the device has no alphaToOne)");
    facts.requestedPath = ShadingPath::Forward;  // the same on both paths
    EXPECT_EQ(planFrame(facts).alphaMasking, AlphaMasking::AlphaTestNoAlphaToOne);
}

TEST(FramePlan, ExplainsThePassesInOrder) {
    FrameFacts facts = visibilityFrame();
    facts.skyboxWanted = false;
    EXPECT_EQ(explainPasses(planFrame(facts), facts, false),
              (std::vector<std::string>{"left out: sheen LUT (no material has a sheen)",
                                        "left out: transmission background (no transmissive material in the frame)",
                                        "left out: skybox (the background is not the environment)"}));
    facts = visibilityFrame();
    facts.sheen = true;
    facts.transmissiveDraws = true;
    facts.transmissionBackgroundDisabled = true;
    const std::vector<std::string> lines = explainPasses(planFrame(facts), facts, true);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0], "sheen LUT: imported (computed by an earlier frame)");
    EXPECT_EQ(lines[1],
              "transmission: 'transmission_background' disabled: 'forward_transmission' draws the transmissive and blended "
              "draws over the opaque image without seeing it (they let through only the background the tonemap composites: "
              "the sky or the background colour)");
    EXPECT_EQ(lines[2], "sky: composited under the image by the tonemap (no skybox pass)");
}

}  // namespace
}  // namespace candela
