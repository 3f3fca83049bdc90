#pragma once
// The frame plan (frame_plan.h) in words: the --explain lines of its decisions. FrameBuilder puts
// each where the frame's other lines about the same work stand. Pure: strings only.

#include "render/frame_plan.h"

#include <string>
#include <vector>

namespace candela {

// The line of one left-out part, e.g. "left out: skybox (debug view)"; `facts` gives its counts.
std::string explainLeftOut(const LeftOut& leftOut, const FrameFacts& facts);
// The lines of the plan's left-out parts among `parts`, in the plan's order.
std::vector<std::string> explainLeftOut(const FramePlan& plan, const FrameFacts& facts, std::initializer_list<PlannedPart> parts);
// "shading path: forward" with the reason a forward frame gives (a visibility frame's line is the
// path's own, VisibilityPath::describe). Precondition: plan.path is Forward.
std::string explainForwardPath(const FramePlan& plan, const FrameFacts& facts);
// What the msaa line adds for alpha-masked materials ("" at one sample), e.g. "; alpha-masked
// materials use alpha to coverage".
std::string explainAlphaMasking(AlphaMasking masking);
// The lines that follow the forward draws': the sheen LUT (`sheenLutComputed`: by an earlier
// frame), transmission, the debug view, the sky and the skybox.
std::vector<std::string> explainPasses(const FramePlan& plan, const FrameFacts& facts, bool sheenLutComputed);

}  // namespace candela
