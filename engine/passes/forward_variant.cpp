#include "passes/forward_variant.h"

#include "scene/scene.h"

namespace candela::passes {

std::string plusLayerNames(uint32_t layers) {
    std::string out;
    for (std::string_view name : scene::layerNames(layers)) (out += "+") += name;
    return out;
}

ForwardVariant forwardVariant(const MaterialKey& key, const FrameVariant& frame) {
    ForwardVariant v;
    v.unlit = key.unlit;
    v.normalMap = key.normalMap;
    v.lights = !key.unlit && frame.lights;
    v.lightTypes = v.lights ? frame.lightTypes : 0;
    v.alphaMask = key.alphaMask;
    v.blend = key.blend;
    v.model = key.unlit ? ShadingModel::Pbr : frame.model;
    v.ibl = !key.unlit && frame.ibl;
    v.irradianceSh = !v.ibl || frame.irradianceSh;
    v.multiscatter = !v.ibl || frame.multiscatter;
    v.referenceSamples = v.ibl ? frame.referenceSamples : 0;
    v.debugView = frame.debugView;
    v.layers = key.layers;
    v.specularAa = !key.unlit && frame.specularAa;
    v.samples = frame.samples;
    v.alphaToCoverage = key.alphaMask && frame.alphaToCoverage;
    return v;
}

std::vector<uint32_t> specializationConstants(const ForwardVariant& v) {
    return {v.normalMap,    v.lights,       v.unlit,    v.alphaMask, static_cast<uint32_t>(v.model),
            v.ibl,          v.irradianceSh, v.multiscatter, v.referenceSamples, static_cast<uint32_t>(v.debugView),
            v.layers,       v.specularAa,   v.alphaToCoverage, 0, 0, 0, v.lightTypes};
}

std::string ForwardVariant::name() const {
    std::string out = unlit ? "unlit" : shadingModelName(model);
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
    if (debugView != DebugView::None) out += std::string("+debug-") + debugViewName(debugView);
    return out;
}

}  // namespace candela::passes
