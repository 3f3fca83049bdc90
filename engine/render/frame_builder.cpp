#include "render/frame_builder.h"

#include "core/errors.h"
#include "core/log.h"
#include "gpu_scene/gpu_scene.h"
#include "passes/backdrop/sky_rays.h"
#include "render/camera_framing.h"
#include "render/explain_plan.h"
#include "shared/tonemap.h"
#include "vk/context.h"
#include "vk/pipeline_cache_file.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <stdexcept>
#include <cmath>

namespace candela {

using namespace graph;

namespace {
constexpr VkFormat kLdrFormat = VK_FORMAT_R8G8B8A8_SRGB;
// A scene frame's 8-bit target when it draws no presentable image: UNORM, the tonemap shader
// encodes sRGB itself, which also lets it dither.
constexpr VkFormat kSceneLdrFormat = VK_FORMAT_R8G8B8A8_UNORM;

// How the tonemap draws the sky the plan places there.
passes::TonemapPass::SkyDraw skyDrawOf(const FramePlan& plan) {
    using SkyDraw = passes::TonemapPass::SkyDraw;
    if (plan.sky != SkyPlacement::Tonemap) return SkyDraw::None;
    if (plan.skyOverClearImage) return SkyDraw::WhereUncoveredImageClear;
    return plan.skyWhereUncovered ? SkyDraw::WhereUncovered : SkyDraw::Everywhere;
}
}  // namespace

FrameBuilder::FrameBuilder(vk::Context& context, SceneState& scene, shader::ParameterRegistry& parameters)
    : mContext(context), mScene(scene), mParameters(parameters), mPattern(context), mEncode(context, kLdrFormat),
      mForward(context), mSkybox(context), mExpand(context), mTransmissionBackground(context), mSkinMorph(context), mTonemap(context),
      mCalibration(context), mAov(context), mVisibility(context) {}

void FrameBuilder::prepareAhead(const passes::MaterialKeys& keys, const RenderSettings& settings, std::span<const scene::Light> lights) {
    std::vector<shading::LightData> data;
    for (const scene::Light& light : lights) data.push_back(gpu_scene::lightData(light));
    mForward.prepareAhead(keys, firstFrameVariant(settings), !lights.empty(), passes::lightTypeBits(data));
    prepareTonemapAhead(settings, &keys);
}

void FrameBuilder::prepareTonemapAhead(const RenderSettings& settings, const passes::MaterialKeys* keys) {
    if (settings.precompile == options::Precompile::Off) return;
    FrameFacts facts = this->facts(settings, msaa(settings.msaa).samples);
    facts.environment = settings.environment != nullptr;  // the maps may be given it only later
    // The ranges the scene's materials fill when every draw is drawn.
    const bool transmissionRange = planDrawList(facts).transmissionRange;
    if (keys)
        for (const passes::MaterialKey& key : keys->keys) {
            const passes::DrawRange range = passes::rangeOf(key, transmissionRange);
            facts.transmissiveDraws = facts.transmissiveDraws || range == passes::DrawRange::Transmissive;
            facts.blendedDraws = facts.blendedDraws || range == passes::DrawRange::Blended;
        }
    const FramePlan plan = planFrame(facts);
    // The target of the frames so far (the viewer's presentable image), else a capture's.
    mTonemap.prepare(mForward.workers(), mTonemap.lastTargetFormat().value_or(kSceneLdrFormat), tonemapOf(settings, plan), skyDrawOf(plan));
}

std::optional<passes::FrameVariant> FrameBuilder::firstFrameVariant(const RenderSettings& settings) const {
    const uint32_t samples = msaa(settings.msaa).samples;
    if (samples > 1) return std::nullopt;
    // A frame asked for the visibility path (or the device's default) may not draw on the forward one.
    if (settings.shadingPath == options::ShadingPath::Visibility ||
        (settings.shadingPath == options::ShadingPath::Auto && defaultShadingPath(mContext).first == options::ShadingPath::Visibility))
        return std::nullopt;
    // As addIbl gives them: the maps have an environment when the settings give one, with the
    // quality's irradiance.
    return passes::frameVariantOf({.model = settings.shading,
                                   .ibl = settings.environment != nullptr,
                                   .irradianceSh = settings.iblQuality.irradiance == ibl::IrradianceMode::Sh9,
                                   .multiscatter = settings.ibl.multiscatter,
                                   .referenceSamples = settings.ibl.referenceSamples,
                                   .debugView = settings.debugView,
                                   .specularAa = settings.shadingOptions.specularAntiAliasing,
                                   .samples = samples},
                                  false, 0);
}

void FrameBuilder::sceneUploaded() {
    mForward.setScene(mScene.gpuScene(), mScene.materialKeys());
    mVisibility.setScene(mScene.gpuScene(), mScene.materialKeys());
    mAov.setScene(mScene.gpuScene(), mScene.materialKeys());
}

vk::MsaaChoice FrameBuilder::msaa(std::optional<uint32_t> requested) const {
    return vk::chooseMsaa(mContext.properties().deviceType, mContext.attachmentSampleCounts(), requested);
}

void FrameBuilder::buildPattern(Frame& frame, const RenderSettings& settings) {
    RenderGraph& graph = *frame.graph;
    frame.hdr = mPattern.add(graph, settings.width, settings.height, settings.patternExposure);
    const TextureId ldr = graph.createTexture("ldr", {.width = settings.width, .height = settings.height, .format = kLdrFormat});
    frame.ldr = mEncode.add(graph, frame.hdr, ldr);
}

void FrameBuilder::buildCalibration(Frame& frame, uint32_t width, uint32_t height) {
    mCalibration.add(*frame.graph, width, height);
}

passes::IblHandles FrameBuilder::addIblMaps(Frame& frame, bool reference) {
    const auto declared = [&] { return static_cast<uint32_t>(frame.graph->declaration().passes.size()); };
    frame.precomputeBegin = declared();
    const passes::IblHandles maps = mScene.iblMaps().addToGraph(*frame.graph, frame.imports, reference);
    frame.precomputeEnd = declared();
    return maps;
}

std::optional<passes::DeformedVertices> FrameBuilder::addSkinMorph(Frame& frame, const FramePlan& plan, const FrameFacts& facts,
                                                                   passes::SkinMorphFrame& work) {
    for (const std::string& line : explainLeftOut(plan, facts, {PlannedPart::SkinMorph})) frame.explanation.push_back(line);
    if (plan.deform != DeformPlan::Deformed && plan.deform != DeformPlan::Disabled) return std::nullopt;
    const gpu_scene::GpuScene& gpuScene = mScene.gpuScene();
    const passes::SkinMorphPass::Inputs inputs{.scene = &gpuScene,
                                               .jobs = work.jobs,
                                               .vertexCount = work.vertexCount,
                                               .frameData = frame.addHostUpload("skin_morph_frame", bytesOf(work.frameData))};
    frame.explanation.push_back("skin_morph: " + std::to_string(work.jobs.size()) + " draws deformed (" +
                          std::to_string(work.skinnedDraws) + " skinned), " + std::to_string(work.activeTargets) +
                          " morph targets with a non-zero weight, " + std::to_string(work.vertexCount) + " vertices (" +
                          formatBytes(uint64_t(work.vertexCount) * sizeof(scene::Vertex)) + " per frame in flight)");
    const BufferId vertices = mSkinMorph.add(*frame.graph, inputs);
    for (const std::string& line : explainLeftOut(plan, facts, {PlannedPart::DeformedDraws})) frame.explanation.push_back(line);
    if (plan.deform == DeformPlan::Disabled) return std::nullopt;
    return passes::DeformedVertices{.vertices = vertices, .vertexOffset = std::move(work.vertexOffset)};
}

passes::PosedBuffers FrameBuilder::addPosedDraws(Frame& frame, const scene::Scene& scene,
                                                            const pose::ScenePose& pose) {
    passes::PosedBuffers posed;
    if (pose.movesNodes()) posed.draws = frame.addHostUpload("posed_draws", bytesOf(gpu_scene::drawDataOf(scene, pose.draws())));
    const gpu_scene::GpuScene& gpuScene = mScene.gpuScene();
    if ((!pose.animatedLights().empty() || !pose.animatedLightProperties().empty()) && mScene.sceneLightsUsed()) {
        // The lights as the buffer holds them (the user's edits included), moved where the pose puts
        // them, dark while their node is hidden, with their animated properties.
        std::vector<shading::LightData> lights = gpuScene.lights();
        for (uint32_t l : pose.animatedLights()) {
            const scene::Light& light = pose.lights()[l];
            const shading::LightData placed = gpu_scene::lightData(light);
            lights[l].positionRange = glm::vec4(glm::vec3(placed.positionRange), lights[l].positionRange.w);
            lights[l].directionType = glm::vec4(glm::vec3(placed.directionType), lights[l].directionType.w);
            // The buffer holds 0 for a light hidden at rest: shown, it takes the scene's intensity.
            if (light.hidden || scene.lights[l].hidden) lights[l].intensity = placed.intensity;
        }
        for (uint32_t l : pose.animatedLightProperties()) {
            const shading::LightData animated = gpu_scene::lightData(pose.lights()[l]);
            lights[l].positionRange.w = animated.positionRange.w;
            lights[l].color = animated.color;
            lights[l].intensity = animated.intensity;
            lights[l].cone = animated.cone;
        }
        posed.lights = frame.addHostUpload("posed_lights", bytesOf(lights));
    }
    if (!pose.animatedMaterials().empty()) {
        // The materials as the buffers hold them (the inspector's edits of the others stay), the
        // animated ones as the pose makes them.
        std::vector<shading::MaterialData> materials = gpuScene.materials();
        for (uint32_t m : pose.animatedMaterials()) materials[m] = gpu_scene::materialData(pose.materials()[m]);
        posed.materials = frame.addHostUpload("posed_materials", bytesOf(materials));
        if (pose.animatesMaterialLayers() && !gpuScene.materialLayers().empty()) {
            std::vector<shading::MaterialLayerData> layers = gpuScene.materialLayers();
            for (uint32_t m : pose.animatedMaterials()) layers[m] = gpu_scene::materialLayerData(pose.materials()[m]);
            posed.materialLayers = frame.addHostUpload("posed_material_layers", bytesOf(layers));
        }
    }
    frame.posed = PosedSummary{.materials = uint32_t(pose.animatedMaterials().size()),
                               .materialLayers = posed.materialLayers.valid(),
                               .lights = uint32_t(pose.animatedLightProperties().size()),
                               .lightsWritten = posed.lights.valid(),
                               .cameras = uint32_t(pose.animatedCameraProperties().size())};
    if (!frame.posed.empty()) frame.explanation.push_back(explainPosed(frame.posed));
    return posed;
}

std::optional<passes::IblInputs> FrameBuilder::addIbl(Frame& frame, const RenderSettings& settings) {
    const ibl_maps::IblMaps& maps = mScene.iblMaps();
    if (!maps.hasEnvironment()) return std::nullopt;
    const float theta = glm::radians(settings.ibl.rotationDegrees);
    const float maxLod = float(maps.specularLevels() - 1);
    return passes::IblInputs{.maps = addIblMaps(frame, settings.ibl.referenceSamples > 0),
                                    .params = {.rotation = glm::vec4(std::cos(theta), std::sin(theta), 0.0f, 0.0f),
                                               .intensity = settings.ibl.intensity,
                                               .maxLod = maxLod,
                                               .skyboxLod = std::clamp(settings.ibl.skyboxBlur, 0.0f, 1.0f) * maxLod,
                                               .lutSize = float(maps.lutSize())},
                                    .irradianceSh = maps.quality().irradiance == ibl::IrradianceMode::Sh9,
                                    .multiscatter = settings.ibl.multiscatter,
                                    .referenceSamples = settings.ibl.referenceSamples};
}

passes::TonemapSettings FrameBuilder::tonemapOf(const RenderSettings& settings, const FramePlan& plan) {
    passes::TonemapSettings tonemap = settings.tonemap;
    if (plan.greyBackground) tonemap.background = shading::srgbDecode(glm::vec3(38.0f / 255.0f));
    if (plan.tonemapLook == TonemapLook::DataAsIs) {
        tonemap.op = options::Tonemap::Linear;
        tonemap.exposureEv = 0.0f;
        tonemap.dither = false;
    }
    return tonemap;
}

FrameFacts FrameBuilder::facts(const RenderSettings& settings, uint32_t samples) const {
    const auto disabled = [&](std::string_view pass) {
        return std::find(settings.disabledPasses.begin(), settings.disabledPasses.end(), pass) != settings.disabledPasses.end();
    };
    const bool environment = mScene.iblMaps().hasEnvironment();
    const auto [devicePath, devicePathReason] = defaultShadingPath(mContext);
    return {.requestedPath = settings.shadingPath,
            .debugView = settings.debugView,
            .skyboxWanted = settings.ibl.skybox,
            .floatOutput = settings.floatOutput,
            .groundTruth = environment && settings.ibl.referenceSamples > 0,
            .samples = samples,
            .skyboxDisabled = disabled("skybox"),
            .transmissionBackgroundDisabled = disabled("transmission_background"),
            .skinMorphDisabled = disabled("skin_morph"),
            .backgroundColour = settings.tonemap.background.has_value(),
            .environment = environment,
            .sheen = mScene.hasSheen(),
            .devicePath = devicePath,
            .devicePathReason = devicePathReason,
            .visibilityUnsupported = mVisibility.unsupported(),
            .integerMsaaSampling = mVisibility.samplesIntegerImages(samples),
            .alphaToOne = mContext.alphaToOne()};
}

void FrameBuilder::buildScene(Frame& frame, const RenderSettings& settings, std::optional<TextureId> target) {
    RenderGraph& graph = *frame.graph;
    const vk::MsaaChoice msaa = this->msaa(settings.msaa);
    if (msaa.clamped && mMsaaWarnedFor != settings.msaa) {
        log::warn("--msaa: " + msaa.reason);
        mMsaaWarnedFor = settings.msaa;
    }
    const scene::Scene& scene = *settings.scene;
    const float aspect = static_cast<float>(settings.width) / static_cast<float>(settings.height);
    const pose::ScenePose* pose = settings.pose ? settings.pose : mScene.restPose();
    const scene::ViewSetup view = resolveView(scene, settings.camera, aspect, pose);
    frame.explanation.push_back("camera: " + cameraFlags(scene, settings.camera, aspect, pose));
    if (!settings.camera.framing.empty()) frame.explanation.push_back("framing: " + settings.camera.framing);

    // The facts the plan decides from: the settings, the device, the pose's deformed draws and
    // the draw list's ranges.
    FrameFacts facts = this->facts(settings, msaa.samples);
    facts.farPlaneAtInfinity = scene::farPlaneAtInfinity(view.projection);
    passes::SkinMorphFrame work;
    if (pose && !scene.deformations.empty()) {
        work = passes::skinMorphFrame(mScene.gpuScene(), *pose);
        facts.deformable = true;
        facts.deformedDraws = static_cast<uint32_t>(work.jobs.size());
    }
    // The plan's first step shapes the draw list: the deformed draws left out, transmissive
    // draws in their own range or not.
    const DrawListPlan listPlan = planDrawList(facts);
    const bool animated = pose && pose->animated();
    std::span<const scene::Draw> draws = animated ? std::span(pose->draws()) : std::span(scene.draws);
    std::vector<scene::Draw> undeformed;
    uint32_t leftOut = 0;  // visible draws hidden here (not counted as hidden by KHR_node_visibility)
    if (listPlan.hidesDeformedDraws()) {
        undeformed.assign(draws.begin(), draws.end());
        for (uint32_t d : pose->deformedDraws()) {
            leftOut += undeformed[d].hidden ? 0 : 1;
            undeformed[d].hidden = true;
        }
        draws = undeformed;
    }
    passes::DrawList list = passes::buildDrawList({.scene = scene,
                                                   .keys = mScene.materialKeys(),
                                                   .draws = draws,
                                                   .view = view,
                                                   .targetHeight = settings.height,
                                                   .selection = settings.drawSelection,
                                                   .transmission = listPlan.transmissionRange});
    list.hiddenDraws -= leftOut;  // their own note says why (addSkinMorph)
    facts.transmissiveDraws = !list.empty(passes::DrawRange::Transmissive);
    facts.blendedDraws = !list.empty(passes::DrawRange::Blended);
    facts.pointAndLineDraws = !list.empty(passes::DrawRange::PointsAndLines);
    FramePlan plan = planFrame(facts);

    const auto deformed = addSkinMorph(frame, plan, facts, work);
    const auto posed = animated ? std::optional(addPosedDraws(frame, scene, *pose)) : std::nullopt;
    const std::optional<passes::IblInputs> ibl = addIbl(frame, settings);
    // The material layers' maps: the sheen LUT (computed once) and, with an environment, the sheen cube.
    std::optional<passes::LayerMaps> layerMaps;
    if (plan.sheenLut) {
        const auto declared = static_cast<uint32_t>(graph.declaration().passes.size());
        layerMaps = passes::LayerMaps{.sheenLut = mScene.sheenLut().addToGraph(graph, frame.imports),
                                      .sheenCube = ibl ? ibl->maps.sheen : TextureId{}};
        if (graph.declaration().passes.size() > declared) frame.sheenLutPass = declared;  // not computed yet
    }
    mParameters.beginFrame();
    mScene.applyParameters(mParameters, mForward.reflection(), mForward.layeredReflection());
    passes::FrameInputs inputs = passes::makeFrameInputs({.view = view,
                                                          .model = settings.shading,
                                                          .ibl = ibl ? &*ibl : nullptr,
                                                          .debugView = settings.debugView,
                                                          .shading = settings.shadingOptions,
                                                          .samples = msaa.samples,
                                                          .alphaToCoverage = plan.alphaMasking == AlphaMasking::AlphaToCoverage,
                                                          .posed = posed ? &*posed : nullptr,
                                                          .deformed = deformed ? &*deformed : nullptr,
                                                          .layerMaps = layerMaps ? &*layerMaps : nullptr},
                                                         mScene.gpuScene());
    // The user's values for the forward programs' push constants, which both paths push.
    mParameters.apply("forward", "Push", mForward.reflection().pushConstants.members, inputs.push);
    // The variants the scene needs now, compiled on the workers and here while the draws ask for
    // them (not one after the other at each first draw); in the viewer, the debug views' after —
    // from the next frame with the same bits on, so that they do not slow the frame that compiles.
    const bool changed = settings.precompile != options::Precompile::Off && mForward.prepare(inputs.variant);
    if (settings.precompile == options::Precompile::DebugViews && !changed) mForward.prepareDebugViews(inputs.variant);
    mStats = list.stats;

    // The visibility path's shading lists are known once the frame's variant is: a frame that
    // needs more than a tile's mask holds is planned again, on the forward path.
    const VisibilityPath::FrameDesc visibility{.size = {settings.width, settings.height, msaa.samples},
                                               .list = list,
                                               .keys = mScene.materialKeys(),
                                               .inputs = inputs,
                                               .recorded = &mStats};
    std::optional<passes::VisibilityFrameTables> tables;
    if (plan.path == options::ShadingPath::Visibility && !(tables = mVisibility.tables(visibility))) {
        facts.shadingListsFit = false;
        plan = planFrame(facts);
    }
    const passes::DrawTarget drawn = addDraws(frame, plan, facts, visibility, tables ? &*tables : nullptr, view, ibl ? &*ibl : nullptr);
    frame.hdr = drawn.hdr;
    addTonemap(frame, settings, plan, target, view, ibl ? &*ibl : nullptr, drawn.depth);
    if (settings.outputs.beyondColor())
        frame.aov = mAov.add(graph, settings.width, settings.height, settings.outputs.aovTargets(), list, inputs);
    else
        frame.explanation.emplace_back("left out: pass 'aov' (no per-pixel output besides colour is asked for: --outputs)");
    passes::ShadingSummary shading = passes::summarizeShading(list, mScene.materialKeys(), scene, mScene.gpuScene().lightCount(),
                                                              inputs.variant, inputs.posed.draws.valid());
    addExplanation(frame, settings, msaa, passes::explainShading(shading, list, settings.drawSelection), plan, facts);
    frame.plan = std::move(plan);
    frame.shading = std::move(shading);
}

passes::DrawTarget FrameBuilder::addDraws(Frame& frame, const FramePlan& plan, const FrameFacts& facts,
                                          const VisibilityPath::FrameDesc& desc, const passes::VisibilityFrameTables* tables,
                                          const scene::ViewSetup& view, const passes::IblInputs* ibl) {
    RenderGraph& graph = *frame.graph;
    if (plan.path == options::ShadingPath::Visibility && !tables)
        throw std::logic_error("FrameBuilder: a visibility frame without its visibility tables");
    if (plan.sky != SkyPlacement::None && !ibl) throw std::logic_error("FrameBuilder: a sky without an environment");
    const auto addSkybox = [&](const passes::DrawTarget& over) {
        return mSkybox.add(graph, view, {.target = over, .specular = ibl->maps.specular, .params = ibl->params}, &mParameters);
    };
    const bool skyboxPass = plan.sky == SkyPlacement::SkyboxPass;
    passes::DrawTarget drawn;
    if (plan.path == options::ShadingPath::Visibility) {
        drawn = mVisibility.add(frame, desc, *tables);
        frame.explanation.push_back(explainVisibility(*frame.visibility));
        // The image is resolved already: the sky goes under it without a depth test.
        if (skyboxPass) {
            const TextureId depth = drawn.depth;
            drawn = addSkybox({.color = drawn.color, .hdr = drawn.hdr});
            drawn.depth = depth;
        }
        if (plan.msaaExpand) drawn = mExpand.add(graph, drawn);
        if (plan.pointsAndLinesPass) drawn = mForward.addPointsAndLines(graph, drawn, desc.list, desc.inputs, desc.recorded);
        if (plan.blendedPass) drawn = mForward.addBlended(graph, drawn, desc.list, desc.inputs, desc.recorded);
    } else {
        frame.explanation.push_back(explainForwardPath(plan, facts));
        drawn = mForward.addOpaque(graph, desc.size, desc.list, desc.inputs, desc.recorded);
        if (skyboxPass) drawn = addSkybox(drawn);
    }
    // Transmissive draws over the opaque image (sky included), which they see through.
    if (plan.transmission != TransmissionPlan::None) {
        const TextureId background = mTransmissionBackground.add(graph, drawn.hdr);
        drawn = mForward.addTransmissive(graph, drawn, plan.transmission == TransmissionPlan::SeesOpaqueImage ? background : TextureId{},
                                         desc.list, desc.inputs, desc.recorded);
    }
    return drawn;
}

void FrameBuilder::addTonemap(Frame& frame, const RenderSettings& settings, const FramePlan& plan, std::optional<TextureId> target,
                              const scene::ViewSetup& view, const passes::IblInputs* ibl, TextureId depth) {
    RenderGraph& graph = *frame.graph;
    const TextureId ldr = target ? *target
                                 : graph.createTexture("ldr", {.width = settings.width,
                                                               .height = settings.height,
                                                               .format = kSceneLdrFormat});
    std::optional<passes::TonemapPass::Sky> sky;
    if (plan.sky == SkyPlacement::Tonemap)
        sky = passes::TonemapPass::Sky{
            .specular = ibl->maps.specular,
            .params = {.rays = passes::skyRays(view.viewProjection, view.eye, ibl->params.rotation, settings.width, settings.height),
                       .intensityLod = glm::vec4(ibl->params.intensity, ibl->params.skyboxLod, 0.0f, 0.0f)},
            .draw = skyDrawOf(plan),
            .depth = depth};
    const passes::TonemapSettings tonemap = tonemapOf(settings, plan);
    frame.solidBackground = tonemap.background.has_value();
    frame.ldr = mTonemap.add(graph, frame.hdr, ldr, tonemap, &mParameters, sky ? &*sky : nullptr);
}

void FrameBuilder::addExplanation(Frame& frame, const RenderSettings& settings, const vk::MsaaChoice& msaa,
                                  std::vector<std::string> shading, const FramePlan& plan, const FrameFacts& facts) {
    std::vector<std::string>& lines = frame.explanation;
    if (!mScene.sceneLightsUsed() && !settings.scene->lights.empty())
        lines.emplace_back("left out: the scene's " + std::to_string(settings.scene->lights.size()) +
                           " punctual lights (--scene-lights off)");
    if (mScene.defaultLightsAdded())
        lines.emplace_back("added: default key and fill lights (the scene has no punctual lights; --no-default-lights)");
    lines.push_back("msaa: " + msaa.reason + explainAlphaMasking(plan.alphaMasking));
    lines.insert(lines.end(), std::make_move_iterator(shading.begin()), std::make_move_iterator(shading.end()));
    const passes::ForwardPass::BuildCounts builds = mForward.buildCounts();
    lines.push_back("forward pipelines: " + std::to_string(builds.built) + " built, " + std::to_string(builds.queued) +
                    " queued ahead of use (" + std::to_string(builds.queuedFinished) + " of them done) (--precompile " +
                    options::precompileName(settings.precompile) + ")");
    lines.push_back("pipeline cache: " + mContext.pipelineCacheFile().status());
    for (const std::string& line : mScene.iblMaps().explanation()) lines.push_back(line);
    for (std::string& line : explainPasses(plan, facts, mScene.sheenLut().computed())) lines.push_back(std::move(line));
}

scene::OrbitCamera FrameBuilder::orbitCamera(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                             const pose::ScenePose* pose) {
    if (camera.orbitCamera) return *camera.orbitCamera;
    const CameraSettings resolved = resolveFraming(scene, camera, aspect, pose, {});
    scene::OrbitCamera out;
    out.target = *resolved.target;
    out.thetaDegrees = resolved.orbit->x;
    out.phiDegrees = resolved.orbit->y;
    out.radius = resolved.orbit->z;
    out.fovYDegrees = *resolved.fovYDegrees;
    out.znear = out.radius * 1e-3f;
    return out;
}

std::string FrameBuilder::cameraFlags(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                      const pose::ScenePose* pose) {
    if (camera.gltfCamera && !camera.orbitCamera) return "--camera " + std::to_string(*camera.gltfCamera);
    if (camera.cameraToWorld || camera.intrinsics) return "a placed camera or intrinsics (no flags give them)";
    return scene::orbitCameraFlags(orbitCamera(scene, camera, aspect, pose));
}

scene::ViewSetup FrameBuilder::resolveView(const scene::Scene& scene, const CameraSettings& camera, float aspect,
                                           const pose::ScenePose* pose) {
    if (pose && !pose->animated()) pose = nullptr;
    if (camera.orbitCamera) {
        scene::ViewSetup view = camera.orbitCamera->view(aspect);
        if (camera.lensShiftX != 0.0f) {
            view.projection = glm::translate(glm::mat4(1.0f), glm::vec3(camera.lensShiftX, 0.0f, 0.0f)) * view.projection;
            view.viewProjection = view.projection * view.view;
        }
        return view;
    }
    if (camera.gltfCamera) {
        if (*camera.gltfCamera >= scene.cameras.size())
            throw UserError("--camera " + std::to_string(*camera.gltfCamera) + ": the scene has " +
                            std::to_string(scene.cameras.size()) + " cameras");
        if (camera.intrinsics) throw UserError("intrinsics apply to the orbit or a placed camera, not to a glTF camera");
        return scene::cameraView((pose ? pose->cameras() : scene.cameras)[*camera.gltfCamera], aspect);
    }
    scene::ViewSetup view = camera.cameraToWorld
                                ? scene::placedView(*camera.cameraToWorld,
                                                    glm::radians(camera.fovYDegrees.value_or(scene::kFramingFovYDegrees)),
                                                    aspect, pose ? pose->bounds() : scene.bounds)
                                : orbitCamera(scene, camera, aspect, pose).view(aspect);
    if (camera.intrinsics) {
        view.projection = scene::perspectiveReverseZ(*camera.intrinsics, view.znear);
        view.viewProjection = view.projection * view.view;
    }
    return view;
}

}  // namespace candela
