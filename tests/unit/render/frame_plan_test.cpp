// The frame plan (render/frame_plan.h): each decision of a scene frame from its facts, checked by
// the plan's fields; and the --explain lines the plan gives (render/explain_plan.h).
#include "render/explain_plan.h"
#include "render/frame_plan.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

using passes::DebugView;
using passes::ShadingPath;

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
    // The device's reason comes before the frame's.
    FrameFacts both = visibilityFrame();
    both.visibilityUnsupported = "no 64-bit atomics";
    both.groundTruth = true;
    EXPECT_EQ(planFrame(both).pathReason, PathReason::Unsupported);
    EXPECT_EQ(explainForwardPath(planFrame(both), both), "shading path: forward (no 64-bit atomics)");
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

TEST(FramePlan, SkyboxLeftOutWithItsReason) {
    FrameFacts facts = visibilityFrame();
    facts.skyboxWanted = false;
    FramePlan plan = planFrame(facts);
    EXPECT_EQ(plan.sky, SkyPlacement::None);
    EXPECT_TRUE(std::count(plan.leftOut.begin(), plan.leftOut.end(), LeftOut{PlannedPart::Skybox, LeftOutReason::NotTheBackground}));
    facts.skyboxWanted = true;
    facts.debugView = DebugView::BaseColor;
    plan = planFrame(facts);
    EXPECT_EQ(plan.sky, SkyPlacement::None);
    EXPECT_TRUE(std::count(plan.leftOut.begin(), plan.leftOut.end(), LeftOut{PlannedPart::Skybox, LeftOutReason::DebugView}));
    // Without an environment there is no sky to leave out.
    facts.environment = false;
    EXPECT_FALSE(planFrame(facts).leavesOut(PlannedPart::Skybox));
}

TEST(FramePlan, TransmissionSeesTheOpaqueImageUnlessItsBackgroundIsDisabled) {
    FrameFacts facts = visibilityFrame();
    EXPECT_EQ(planFrame(facts).transmission, TransmissionPlan::None);
    EXPECT_TRUE(std::count(planFrame(facts).leftOut.begin(), planFrame(facts).leftOut.end(),
                           LeftOut{PlannedPart::TransmissionBackground, LeftOutReason::NoTransmissive}));
    facts.transmissiveDraws = true;
    EXPECT_EQ(planFrame(facts).transmission, TransmissionPlan::SeesOpaqueImage);
    EXPECT_FALSE(planFrame(facts).leavesOut(PlannedPart::TransmissionBackground));
    facts.transmissionBackgroundDisabled = true;
    EXPECT_EQ(planFrame(facts).transmission, TransmissionPlan::Blind);
    FrameFacts debug = visibilityFrame();
    debug.debugView = DebugView::BaseColor;  // the draw list then has no transmissive range
    const FramePlan plan = planFrame(debug);
    EXPECT_TRUE(std::count(plan.leftOut.begin(), plan.leftOut.end(),
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
    EXPECT_EQ(plan.deform, DeformPlan::Disabled);
    EXPECT_EQ(explainLeftOut(plan, facts, {PlannedPart::DeformedDraws}),
              std::vector<std::string>{"left out: the 3 deformed draws (skin_morph disabled: nothing places their vertices)"});
}

TEST(FramePlan, SheenLutOnlyForSheen) {
    FrameFacts facts = visibilityFrame();
    EXPECT_FALSE(planFrame(facts).sheenLut);
    EXPECT_TRUE(planFrame(facts).leavesOut(PlannedPart::SheenLut));
    facts.sheen = true;
    EXPECT_TRUE(planFrame(facts).sheenLut);
    EXPECT_FALSE(planFrame(facts).leavesOut(PlannedPart::SheenLut));
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
    EXPECT_EQ(lines[1].rfind("transmission: 'transmission_background' disabled", 0), 0u) << lines[1];
    EXPECT_EQ(lines[2], "sky: composited under the image by the tonemap (no skybox pass)");
}

}  // namespace
}  // namespace candela
