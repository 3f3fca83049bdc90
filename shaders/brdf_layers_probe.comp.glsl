#version 460
#extension GL_GOOGLE_include_directive : require
// The layered BRDF probe: brdf_probe.comp's grid (shared/brdf_probe.h) evaluated with the specular
// layer of the push constants (shared/brdf_layers.h: KHR_materials_ior and _specular), as the
// forward pass's layered program does — the Cook-Torrance models with the layer's dielectric
// Fresnel, Blinn-Phong as in the core. rgb = f · N·L · intensity, a = the combination's index.
#include "shared/brdf_layers.h"
#include "shared/brdf_probe.h"

layout(local_size_x = CANDELA_BRDF_PROBE_GROUP_SIZE, local_size_y = CANDELA_BRDF_PROBE_GROUP_SIZE) in;

layout(set = 0, binding = 0, rgba32f) uniform writeonly image2D outImage;

layout(push_constant) uniform Push {
    BrdfProbeParams params;
};

void main() {
    uvec2 texel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(texel, uvec2(CANDELA_BRDF_PROBE_WIDTH, CANDELA_BRDF_PROBE_HEIGHT)))) return;
    BrdfProbeSample s = brdfProbeSample(texel);
    vec3 radiance;
    if (s.model == CANDELA_SHADING_BLINN_PHONG) {
        radiance = brdfTimesCosine(s.N, s.V, s.L, s.baseColor, s.metallic, s.perceptualRoughness, s.model);
    } else {
        DielectricFresnel d = dielectricFresnel(params.ior, params.specularColor.rgb, params.specular);
        BrdfLobes lobes = brdfLobesTimesCosineDielectric(s.N, s.V, s.L, s.baseColor, s.metallic, s.perceptualRoughness,
                                                         s.model, d);
        radiance = lobes.diffuse + lobes.specular;
    }
    float index = float(texel.y * CANDELA_BRDF_PROBE_WIDTH + texel.x);
    imageStore(outImage, ivec2(texel), vec4(radiance * params.intensity, index));
}
