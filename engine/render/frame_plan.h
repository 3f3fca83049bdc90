#pragma once
// The frame plan: what a scene frame draws and where, decided by one pure function (planFrame) from
// the frame's settings, the scene's facts and the device's capabilities — the shading path, where
// the sky goes, how transmissive draws see what is behind them, whether the visibility path needs
// the MSAA expansion and the blended pass, what the skin_morph pass does, how alpha-masked draws cut
// their edges, how the tonemap shows a debug view — with every pass or draw it leaves out and why, as enums. No graph and no Vulkan: each
// decision is unit-tested by its fields (tests/unit/render/frame_plan_test.cpp). FrameBuilder
// gathers the facts, declares the plan's passes and turns the plan into --explain lines
// (explain_plan.h).

#include "options/debug_view.h"
#include "options/shading_path.h"

#include <cstdint>
#include <string>
#include <vector>

namespace candela {

// What planFrame decides from.
struct FrameFacts {
    // ---- The frame's settings.
    options::ShadingPath requestedPath = options::ShadingPath::Auto;
    options::DebugView debugView = options::DebugView::None;
    bool skyboxWanted = true;       // the environment is the background (IblLook::skybox)
    bool floatOutput = false;       // the HDR image is the output (EXR/PFM)
    bool groundTruth = false;       // ibl-report's ground truth (reference samples > 0, with an environment)
    uint32_t samples = 1;           // the sample count chosen for the draw targets
    bool skyboxDisabled = false;    // --disable-pass skybox (the viewer's toggle)
    bool transmissionBackgroundDisabled = false;
    bool skinMorphDisabled = false;
    bool backgroundColour = false;  // the settings give the background a colour (TonemapSettings::background)
    // ---- The scene's.
    bool environment = false;       // the IBL maps have an environment
    bool sheen = false;             // a material has a sheen (the layered program reads the sheen LUT)
    bool deformable = false;        // the scene has skins or morph targets
    uint32_t deformedDraws = 0;     // draws the pose deforms (skinned, or a non-zero morph weight)
    bool transmissiveDraws = false; // the draw list has transmissive draws (debug views have none)
    bool blendedDraws = false;
    bool pointAndLineDraws = false;  // the draw list has opaque or masked point or line draws
    bool shadingListsFit = true;    // the visibility path's shading lists fit a tile's mask
    bool farPlaneAtInfinity = true; // the view's (scene::farPlaneAtInfinity): else geometry at its far plane has the cleared depth 0
    // ---- The device's.
    options::ShadingPath devicePath = options::ShadingPath::Forward;  // what `auto` takes
    std::string devicePathReason;   // why (the device's words)
    std::string visibilityUnsupported;  // why the device or the scene cannot take the visibility path ("": it can)
    bool integerMsaaSampling = true;    // the device samples integer images at `samples` samples
    bool alphaToOne = false;            // the device has alphaToOne (alpha to coverage storing alpha 1)
};

// Why a frame takes the forward path when the visibility path was not asked for or cannot be taken.
enum class PathReason : uint8_t {
    Requested,            // the path asked for (or, for auto, the device's default visibility path)
    DeviceDefault,        // auto: the device's default (FrameFacts::devicePathReason)
    Unsupported,          // the device or the scene cannot (FrameFacts::visibilityUnsupported)
    GroundTruth,          // ibl-report's ground truth is a forward program
    IntegerMsaaSampling,  // the device cannot sample the multisampled visibility image
    TooManyShadingLists,  // more shading lists than a tile's mask holds
};

enum class SkyPlacement : uint8_t {
    None,        // no environment, a debug view, or the environment is not the background
    Tonemap,     // composited under the image by the tonemap (one full-screen pass fewer)
    SkyboxPass,  // drawn into the HDR image by the skybox pass (transmissive draws see it, or it is the output)
};

enum class TransmissionPlan : uint8_t {
    None,             // no transmissive draw
    SeesOpaqueImage,  // transmission_background copies the opaque image; forward_transmission reads it
    Blind,            // transmission_background disabled: transmissive draws see only what the tonemap composites
};

enum class DeformPlan : uint8_t {
    Static,      // the scene has no skins or morph targets
    NoneInPose,  // nothing is deformed in this pose: no skin_morph pass
    Deformed,    // skin_morph deforms the pose's draws
    Disabled,    // skin_morph is declared (switched off): the deformed draws are left out
};

// How alpha-masked draws cut their edges, on both paths.
enum class AlphaMasking : uint8_t {
    AlphaTest,              // one sample: the alpha test
    AlphaToCoverage,        // MSAA: coverage from alpha (stored alpha 1: alphaToOne)
    AlphaTestNoAlphaToOne,  // MSAA, but the device has no alphaToOne: the alpha test
};

// How the tonemap shows a frame: as set, or, in a debug view of data (material inputs, normals, GGX
// terms), the values as they are — linear, exposure 0, no dither. Debug views of light (the lobes'
// light) are tone mapped as set.
enum class TonemapLook : uint8_t { AsSet, DataAsIs };

// What a plan leaves out, and why.
enum class PlannedPart : uint8_t { SkinMorph, DeformedDraws, SheenLut, TransmissionBackground, Skybox };
enum class LeftOutReason : uint8_t {
    NothingDeformed,    // skin_morph: no draw is skinned or has a non-zero morph weight in this pose
    SkinMorphDisabled,  // the deformed draws: nothing places their vertices
    NoSheen,            // sheen LUT: no material has a sheen
    NoTransmissive,     // transmission background: no transmissive material in the frame
    DebugView,          // a debug view shows data (transmissive draws with the rest; no sky)
    NotTheBackground,   // skybox: the environment is not the background
};
struct LeftOut {
    PlannedPart part;
    LeftOutReason reason;
    bool operator==(const LeftOut&) const = default;
};

// The first step of a frame's plan, taken before its draw list is built because it shapes the
// list: what skin_morph does — when it is switched off, the pose's deformed draws have nothing to
// place their vertices and the list leaves them out — and whether transmissive draws get their own
// range (drawn over the opaque image) or are drawn with the rest (a debug view shows data, not what
// lies behind). planFrame takes the same decisions from the same facts.
struct DrawListPlan {
    DeformPlan deform = DeformPlan::Static;
    bool transmissionRange = true;
    // Whether the list leaves out the pose's deformed draws.
    bool hidesDeformedDraws() const { return deform == DeformPlan::Disabled; }
    bool operator==(const DrawListPlan&) const = default;
};

// Reads the settings' and the pose's facts only (none of the draw list's).
DrawListPlan planDrawList(const FrameFacts& facts);

struct FramePlan {
    options::ShadingPath path = options::ShadingPath::Forward;  // Forward or Visibility
    PathReason pathReason = PathReason::Requested;
    DeformPlan deform = DeformPlan::Static;
    SkyPlacement sky = SkyPlacement::None;
    TransmissionPlan transmission = TransmissionPlan::None;
    // The tonemap's sky only where nothing was drawn (the scene's depth still at the far plane):
    // one sample (the depth then matches the image) and no transmissive draws (which write depth
    // and may let the sky through). Depth-tested, so the rasterizer leaves covered pixels out of
    // the sky's program, which a branch in the shader does not do on llvmpipe.
    bool skyWhereUncovered = false;
    // And no blended draws either, which leave the depth as it was but not the image, and a far
    // plane at infinity, whose depth no geometry reaches: where the depth is the far plane's the
    // image then holds its clear value, which the sky's draw does not read
    // (TonemapPass::SkyDraw::WhereUncoveredImageClear).
    bool skyOverClearImage = false;
    bool sheenLut = false;       // the layered program reads the sheen LUT (computed once, then imported)
    bool msaaExpand = false;     // visibility path at MSAA: forward draws after it need a multisampled image
    bool pointsAndLinesPass = false;  // visibility path: forward_points_lines draws the points and lines
    bool blendedPass = false;    // visibility path: forward_blended draws the blended draws (no transmissive ones)
    AlphaMasking alphaMasking = AlphaMasking::AlphaTest;
    TonemapLook tonemapLook = TonemapLook::AsSet;
    // A debug view has no sky: where the environment was the background (and no colour is given),
    // the tonemap puts a neutral grey (#262626) behind the data instead.
    bool greyBackground = false;
    std::vector<LeftOut> leftOut;

    // Whether the plan leaves out `part` (for any reason).
    bool leavesOut(PlannedPart part) const;
    bool operator==(const FramePlan&) const = default;
};

// The plan of a frame with `facts`.
FramePlan planFrame(const FrameFacts& facts);

}  // namespace candela
