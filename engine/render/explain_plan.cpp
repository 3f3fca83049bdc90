#include "render/explain_plan.h"

#include "shared/visibility.h"

#include <algorithm>

namespace candela {

std::string explainLeftOut(const LeftOut& leftOut, const FrameFacts& facts) {
    switch (leftOut.part) {
        case PlannedPart::SkinMorph: return "left out: skin_morph (no draw is skinned or has a non-zero morph weight in this pose)";
        case PlannedPart::DeformedDraws:
            return "left out: the " + std::to_string(facts.deformedDraws) +
                   " deformed draws (skin_morph disabled: nothing places their vertices)";
        case PlannedPart::SheenLut: return "left out: sheen LUT (no material has a sheen)";
        case PlannedPart::TransmissionBackground:
            return leftOut.reason == LeftOutReason::DebugView
                       ? "left out: transmission background (debug view: transmissive draws show data)"
                       : "left out: transmission background (no transmissive material in the frame)";
        case PlannedPart::Skybox:
            return leftOut.reason == LeftOutReason::DebugView ? "left out: skybox (debug view)"
                                                              : "left out: skybox (the background is not the environment)";
    }
    return {};
}

std::vector<std::string> explainLeftOut(const FramePlan& plan, const FrameFacts& facts, std::initializer_list<PlannedPart> parts) {
    std::vector<std::string> out;
    for (const LeftOut& leftOut : plan.leftOut)
        if (std::find(parts.begin(), parts.end(), leftOut.part) != parts.end()) out.push_back(explainLeftOut(leftOut, facts));
    return out;
}

std::string explainAlphaMasking(AlphaMasking masking) {
    switch (masking) {
        case AlphaMasking::AlphaTest: return "";
        case AlphaMasking::AlphaToCoverage: return "; alpha-masked materials use alpha to coverage";
        case AlphaMasking::AlphaTestNoAlphaToOne:
            return "; alpha-masked materials keep the alpha test (the device has no alphaToOne)";
    }
    return "";
}

std::string explainForwardPath(const FramePlan& plan, const FrameFacts& facts) {
    std::string reason;
    switch (plan.pathReason) {
        case PathReason::Requested: break;
        case PathReason::DeviceDefault: reason = facts.devicePathReason; break;
        case PathReason::Unsupported: reason = facts.visibilityUnsupported; break;
        case PathReason::GroundTruth: reason = "the ground truth of ibl-report is a forward program"; break;
        case PathReason::IntegerMsaaSampling:
            reason = "the device cannot sample a " + std::to_string(facts.samples) + "-sample integer image (the visibility image)";
            break;
        case PathReason::TooManyShadingLists:
            reason = "the frame needs more than " + std::to_string(CANDELA_VISIBILITY_MAX_LISTS) +
                     " shading lists, the visibility path's limit";
            break;
    }
    return "shading path: forward" + (reason.empty() ? std::string() : " (" + reason + ")");
}

std::vector<std::string> explainPasses(const FramePlan& plan, const FrameFacts& facts, bool sheenLutComputed) {
    std::vector<std::string> out;
    if (plan.sheenLut)
        out.emplace_back(sheenLutComputed ? "sheen LUT: imported (computed by an earlier frame)"
                                          : "sheen LUT: computed by this frame's ibl_sheen_lut pass (once per run)");
    else
        out.push_back(explainLeftOut({PlannedPart::SheenLut, LeftOutReason::NoSheen}, facts));
    switch (plan.transmission) {
        case TransmissionPlan::Blind:
            out.emplace_back("transmission: 'transmission_background' disabled: 'forward_transmission' draws the transmissive "
                             "and blended draws over the opaque image without seeing it (they let through only the background "
                             "the tonemap composites: the sky or the background colour)");
            break;
        case TransmissionPlan::SeesOpaqueImage:
            out.emplace_back("transmission: 'transmission_background' copies the opaque image into a mip chain; "
                             "'forward_transmission' draws the transmissive and blended draws over it");
            break;
        case TransmissionPlan::None:
            for (const std::string& line : explainLeftOut(plan, facts, {PlannedPart::TransmissionBackground})) out.push_back(line);
            break;
    }
    if (facts.debugView != options::DebugView::None)
        out.push_back(std::string("debug view: ") + options::debugViewName(facts.debugView) +
                      (plan.tonemapLook == TonemapLook::DataAsIs ? " (shown as data: linear tonemap at exposure 0)"
                                                                  : " (tonemapped as the image is)"));
    if (plan.sky == SkyPlacement::Tonemap)
        out.emplace_back(plan.skyOverClearImage ? "sky: composited by the tonemap where nothing was drawn (depth-tested, the "
                                                  "image not read there: no blended draws; no skybox pass)"
                         : plan.skyWhereUncovered
                             ? "sky: composited by the tonemap where nothing was drawn (depth-tested; no skybox pass)"
                             : "sky: composited under the image by the tonemap (no skybox pass)");
    for (const std::string& line : explainLeftOut(plan, facts, {PlannedPart::Skybox})) out.push_back(line);
    return out;
}

}  // namespace candela
