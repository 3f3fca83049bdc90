#include "passes/drawing/frame_inputs.h"

namespace candela::passes {

using namespace graph;

uint32_t lightTypeBits(std::span<const shading::LightData> lights) {
    uint32_t types = 0;
    for (const shading::LightData& light : lights) types |= 1u << static_cast<uint32_t>(light.directionType.w);
    return types;
}

FrameVariant frameVariantOf(const FrameVariantSource& source, bool lights, uint32_t lightTypes) {
    return {.model = source.model,
            .lights = lights,
            .lightTypes = lightTypes,
            .ibl = source.ibl,
            .irradianceSh = !source.ibl || source.irradianceSh,
            .multiscatter = !source.ibl || source.multiscatter,
            .referenceSamples = source.ibl ? source.referenceSamples : 0,
            .debugView = source.debugView,
            .specularAa = source.specularAa,
            .samples = source.samples,
            .alphaToCoverage = source.samples > 1 && source.alphaToCoverage};
}

FrameInputs makeFrameInputs(const FrameInputsDesc& desc, const gpu_scene::GpuScene& scene) {
    FrameInputs out;
    out.variant = frameVariantOf({.model = desc.model,
                                  .ibl = desc.ibl != nullptr,
                                  .irradianceSh = desc.ibl && desc.ibl->irradianceSh,
                                  .multiscatter = desc.ibl && desc.ibl->multiscatter,
                                  .referenceSamples = desc.ibl ? desc.ibl->referenceSamples : 0,
                                  .debugView = desc.debugView,
                                  .specularAa = desc.shading.specularAntiAliasing,
                                  .samples = desc.samples,
                                  .alphaToCoverage = desc.alphaToCoverage},
                                 scene.lightCount() > 0, lightTypeBits(scene.lights()));
    out.push.viewProjection = desc.view.viewProjection;
    out.push.eye = glm::vec4(desc.view.eye, 1.0f);
    out.push.counts = glm::uvec4(scene.lightCount(), 0, 0, 0);
    if (desc.ibl) {
        out.push.ibl = desc.ibl->params;
        out.ibl = desc.ibl->maps;
    }
    if (desc.layerMaps) out.layerMaps = *desc.layerMaps;
    if (desc.posed) out.posed = *desc.posed;
    if (desc.deformed) {
        out.deformed = desc.deformed->vertices;
        out.vertexOffset = desc.deformed->vertexOffset;
    }
    return out;
}

DeclaredFrameBuffers declareFrameReads(PassBuilder& builder, const FrameInputs& frame, const FrameReads& reads) {
    DeclaredFrameBuffers out;
    const PosedBuffers& posed = frame.posed;
    if (posed.draws.valid()) out.posed.draws = builder.read(posed.draws, Usage::StorageRead, reads.sceneStages);
    if (posed.lights.valid() && reads.lights) out.posed.lights = builder.read(posed.lights, Usage::StorageRead, reads.lightStages);
    if (posed.materials.valid() && reads.materials)
        out.posed.materials = builder.read(posed.materials, Usage::StorageRead, reads.sceneStages);
    if (posed.materialLayers.valid() && reads.materialLayers)
        out.posed.materialLayers = builder.read(posed.materialLayers, Usage::StorageRead, reads.sceneStages);
    if (frame.deformed.valid()) out.deformed = builder.read(frame.deformed, reads.deformedUsage);
    return out;
}

}  // namespace candela::passes
