#version 460
#extension GL_GOOGLE_include_directive : require
// The BRDF probe: one invocation per combination of the grid in shared/brdf_probe.h evaluates the
// forward pass's brdfTimesCosine (shared/brdf.h) and stores rgb = f · N·L · intensity and
// a = the combination's linear index (y · width + x), so a test can check every value against its
// double-precision reference and that both sides enumerated the same combination. With kLayers,
// the Cook-Torrance models evaluate the layers of the push constants (shared/brdf_layers.h: the
// specular layer, the thin film, the anisotropy, the transmission, the diffuse transmission, the sheen, the clearcoat) with the
// function the forward pass's layered program uses;
// Blinn-Phong stays the core's there too.
#include "shared/brdf_layers.h"
#include "shared/brdf_probe.h"
#include "shared/specialization_ids.h"

layout(constant_id = CANDELA_SPEC_PROBE_LAYERS) const bool kLayers = false;

layout(local_size_x = CANDELA_BRDF_PROBE_GROUP_SIZE, local_size_y = CANDELA_BRDF_PROBE_GROUP_SIZE) in;

layout(set = 0, binding = 0, rgba32f) uniform writeonly image2D outImage;

layout(push_constant) uniform Push {
    BrdfProbeParams params;
};

void main() {
    uvec2 texel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(texel, uvec2(CANDELA_BRDF_PROBE_WIDTH, CANDELA_BRDF_PROBE_HEIGHT)))) return;
    BrdfProbeSample s = brdfProbeSample(texel);
    if (params.transmission.y > 0.5f) s.L.z = -s.L.z;
    vec3 radiance;
    if (kLayers && s.model != CANDELA_SHADING_BLINN_PHONG) {
        // The core Fresnel unless the specular layer is probed (as the forward pass: the transmission
        // weighs by it too).
        DielectricFresnel d = (params.layers & CANDELA_LAYER_SPECULAR) != 0u
                                  ? dielectricFresnel(params.ior, params.specularColor.rgb, params.specular)
                                  : coreDielectricFresnel();
        if ((params.layers & CANDELA_LAYER_IRIDESCENCE) != 0u)
            d = withThinFilm(d, params.iridescence.x, params.iridescence.y, params.iridescence.z, params.iridescence.w,
                             clamp(dot(s.N, s.V), CANDELA_MIN_NOV, 1.0f), s.baseColor);
        Clearcoat coat = clearcoatLayer(params.clearcoat, params.clearcoatRoughness, params.clearcoatNormal.xyz, s.V);
        Sheen sheen = sheenLayer(params.sheenColor.rgb, params.sheenRoughness, params.sheenAlbedo);
        Anisotropy an = anisotropyLayer(params.anisotropy.w, params.anisotropy.xyz, cross(s.N, params.anisotropy.xyz));
        Transmission tr = transmissionLayer(params.transmission.x, s.perceptualRoughness, params.ior);
        DiffuseTransmission dt = diffuseTransmissionLayer(
            params.transmission.z, brdfProbeDiffuseTransmissionColor(uint(params.transmission.w)));
        LayeredLobes lobes = layeredLobesTimesCosine(s.N, s.V, s.L, s.L, s.baseColor, s.metallic, s.perceptualRoughness, s.model,
                                                     params.layers, d, an, tr, dt, sheen, coat);
        radiance = lobes.diffuse + lobes.specular + lobes.transmission + lobes.diffuseTransmission + lobes.sheen +
                   vec3(lobes.clearcoat);
    } else {
        radiance = brdfTimesCosine(s.N, s.V, s.L, s.baseColor, s.metallic, s.perceptualRoughness, s.model);
    }
    float index = float(texel.y * CANDELA_BRDF_PROBE_WIDTH + texel.x);
    imageStore(outImage, ivec2(texel), vec4(radiance * params.intensity, index));
}
