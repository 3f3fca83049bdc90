#include "render/frame_plan.h"

#include <algorithm>
#include <tuple>

namespace candela {

using options::ShadingPath;

namespace {

std::pair<ShadingPath, PathReason> choosePath(const FrameFacts& facts) {
    if (facts.requestedPath == ShadingPath::Forward) return {ShadingPath::Forward, PathReason::Requested};
    if (facts.requestedPath == ShadingPath::Auto && facts.devicePath == ShadingPath::Forward)
        return {ShadingPath::Forward, PathReason::DeviceDefault};
    if (!facts.visibilityUnsupported.empty()) return {ShadingPath::Forward, PathReason::Unsupported};
    if (facts.groundTruth) return {ShadingPath::Forward, PathReason::GroundTruth};
    if (facts.samples > 1 && !facts.integerMsaaSampling) return {ShadingPath::Forward, PathReason::IntegerMsaaSampling};
    if (!facts.shadingListsFit) return {ShadingPath::Forward, PathReason::TooManyShadingLists};
    return {ShadingPath::Visibility, PathReason::Requested};
}

}  // namespace

bool FramePlan::leavesOut(PlannedPart part) const {
    return std::any_of(leftOut.begin(), leftOut.end(), [&](const LeftOut& l) { return l.part == part; });
}

DrawListPlan planDrawList(const FrameFacts& facts) {
    DrawListPlan plan;
    if (facts.deformable)
        plan.deform = facts.deformedDraws == 0 ? DeformPlan::NoneInPose
                      : facts.skinMorphDisabled ? DeformPlan::Disabled
                                                : DeformPlan::Deformed;
    plan.transmissionRange = facts.debugView == options::DebugView::None;
    return plan;
}

FramePlan planFrame(const FrameFacts& facts) {
    FramePlan plan;
    std::tie(plan.path, plan.pathReason) = choosePath(facts);
    const bool debugView = facts.debugView != options::DebugView::None;

    plan.deform = planDrawList(facts).deform;
    if (plan.deform == DeformPlan::NoneInPose) plan.leftOut.push_back({PlannedPart::SkinMorph, LeftOutReason::NothingDeformed});
    if (plan.deform == DeformPlan::Disabled)
        plan.leftOut.push_back({PlannedPart::DeformedDraws, LeftOutReason::SkinMorphDisabled});

    plan.sheenLut = facts.sheen;
    if (!facts.sheen) plan.leftOut.push_back({PlannedPart::SheenLut, LeftOutReason::NoSheen});

    // Switching transmission_background off leaves the transmissive draws without the opaque image
    // to see through: they are drawn over it reading a placeholder (black, coverage 0), so what they
    // let through is what the tonemap composites where coverage is below 1 — the sky or the
    // background colour, not the scene behind them (the pass is declared, to be disabled).
    if (facts.transmissiveDraws)
        plan.transmission = facts.transmissionBackgroundDisabled ? TransmissionPlan::Blind : TransmissionPlan::SeesOpaqueImage;
    else
        plan.leftOut.push_back({PlannedPart::TransmissionBackground, debugView ? LeftOutReason::DebugView : LeftOutReason::NoTransmissive});

    // The sky: composited under the image by the tonemap, unless the transmissive draws must see
    // it or the HDR image is the output (then the skybox pass draws it into the HDR image).
    // Switching the skybox pass off still switches the sky off: the pass is then declared, to be
    // disabled.
    const bool sky = facts.environment && facts.skyboxWanted && !debugView;
    if (sky) {
        const bool inTonemap = plan.transmission != TransmissionPlan::SeesOpaqueImage && !facts.floatOutput && !facts.skyboxDisabled;
        plan.sky = inTonemap ? SkyPlacement::Tonemap : SkyPlacement::SkyboxPass;
        plan.skyWhereUncovered = inTonemap && facts.samples == 1 && plan.transmission == TransmissionPlan::None;
        plan.skyOverClearImage = plan.skyWhereUncovered && !facts.blendedDraws && facts.farPlaneAtInfinity;
    } else if (facts.environment) {
        plan.leftOut.push_back({PlannedPart::Skybox, debugView ? LeftOutReason::DebugView : LeftOutReason::NotTheBackground});
    }

    if (debugView) {
        if (!options::debugViewIsLight(facts.debugView)) plan.tonemapLook = TonemapLook::DataAsIs;
        plan.greyBackground = facts.environment && facts.skyboxWanted && !facts.backgroundColour;
    }

    if (facts.samples > 1)
        plan.alphaMasking = facts.alphaToOne ? AlphaMasking::AlphaToCoverage : AlphaMasking::AlphaTestNoAlphaToOne;

    if (plan.path == ShadingPath::Visibility) {
        // The visibility path's image is resolved: the draws drawn forward after it (points and lines,
        // which the visibility buffer does not hold, blended and transmissive draws) need one at
        // the frame's sample count at MSAA; the points and lines follow in their own pass, then the
        // blended draws in theirs unless the transmissive pass draws them.
        plan.msaaExpand = facts.samples > 1 && (facts.transmissiveDraws || facts.blendedDraws || facts.pointAndLineDraws);
        plan.pointsAndLinesPass = facts.pointAndLineDraws;
        plan.blendedPass = !facts.transmissiveDraws && facts.blendedDraws;
    }
    return plan;
}

}  // namespace candela
