#include "passes/drawing/shading_variant.h"

#include "scene/scene.h"
#include "shared/specialization_ids.h"
#include "shader/specialize.h"

namespace candela::passes {

std::string plusLayerNames(uint32_t layers) {
    std::string out;
    for (std::string_view name : scene::layerNames(layers)) (out += "+") += name;
    return out;
}

ShadingVariant shadingVariant(const MaterialKey& key, const FrameVariant& frame) {
    ShadingVariant v;
    v.unlit = key.unlit;
    v.normalMap = key.normalMap;
    v.lights = !key.unlit && frame.lights;
    v.lightTypes = v.lights ? frame.lightTypes : 0;
    v.alphaMask = key.alphaMask;
    v.blend = key.blend;
    v.model = key.unlit ? options::ShadingModel::Pbr : frame.model;
    v.ibl = !key.unlit && frame.ibl;
    v.irradianceSh = !v.ibl || frame.irradianceSh;
    v.multiscatter = !v.ibl || frame.multiscatter;
    v.referenceSamples = v.ibl ? frame.referenceSamples : 0;
    v.debugView = frame.debugView;
    v.layers = key.layers;
    v.specularAa = !key.unlit && frame.specularAa;
    v.samples = frame.samples;
    v.alphaToCoverage = key.alphaMask && frame.alphaToCoverage;
    v.topology = key.topology;
    return v;
}

std::vector<uint32_t> specializationConstants(const ShadingVariant& v) {
    return shader::specializationValues({{CANDELA_SPEC_NORMAL_MAP, v.normalMap},
                                         {CANDELA_SPEC_LIGHTS, v.lights},
                                         {CANDELA_SPEC_UNLIT, v.unlit},
                                         {CANDELA_SPEC_ALPHA_MASK, v.alphaMask},
                                         {CANDELA_SPEC_SHADING_MODEL, static_cast<uint32_t>(v.model)},
                                         {CANDELA_SPEC_IBL, v.ibl},
                                         {CANDELA_SPEC_IRRADIANCE_SH, v.irradianceSh},
                                         {CANDELA_SPEC_MULTISCATTER, v.multiscatter},
                                         {CANDELA_SPEC_REFERENCE_SAMPLES, v.referenceSamples},
                                         {CANDELA_SPEC_DEBUG_VIEW, static_cast<uint32_t>(v.debugView)},
                                         {CANDELA_SPEC_LAYERS, v.layers},
                                         {CANDELA_SPEC_SPECULAR_AA, v.specularAa},
                                         {CANDELA_SPEC_ALPHA_TO_COVERAGE, v.alphaToCoverage},
                                         {CANDELA_SPEC_LIGHT_TYPES, v.lightTypes}});
}

std::string ShadingVariant::name() const {
    std::string out = unlit ? "unlit" : options::shadingModelName(model);
    if (normalMap) out += "+normal-map";
    if (!unlit && !lights) out += "+no-lights";
    if (alphaMask) out += "+alpha-mask";
    if (blend) out += "+blend";
    if (ibl && !unlit) out += std::string("+ibl-") + (irradianceSh ? "sh9" : "cube") + (multiscatter ? "" : "-single-scatter") +
               (referenceSamples ? "-reference" + std::to_string(referenceSamples) : "");
    out += plusLayerNames(layers);
    if (specularAa && !unlit) out += "+specular-aa";
    if (samples > 1) out += "+msaa" + std::to_string(samples);
    if (alphaToCoverage) out += "+alpha-to-coverage";
    if (debugView != options::DebugView::None) out += std::string("+debug-") + options::debugViewName(debugView);
    if (topology != scene::Topology::Triangles) (out += "+") += scene::topologyName(topology);
    return out;
}

}  // namespace candela::passes
