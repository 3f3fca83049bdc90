// The ground truth of `candela ibl-report`: the reflectance equation integrated per pixel against
// the environment itself, in place of the split sum. Included only by the report's own program
// (forward_reference.frag, core materials: it integrates the core BRDF and knows no layers);
// its inputs, set 2 bindings 4 and 5, are declared in shading/resources.glsl.
#ifndef CANDELA_FORWARD_REFERENCE_IBL_GLSL
#define CANDELA_FORWARD_REFERENCE_IBL_GLSL

#include "shading/resources.glsl"
#include "shading/surface.glsl"
#include "shared/environment.h"
#include "shared/ibl.h"

// The number of GGX and of cosine samples per pixel (ForwardPass::Variant::referenceSamples).
layout(constant_id = CANDELA_SPEC_REFERENCE_SAMPLES) const uint kReferenceSamples = 0u;

// Radiance of the environment in world direction `d` for the ground truth: its equirectangular
// texel (piecewise constant); with `skipSummed`, 0 for the texels summed explicitly.
vec3 referenceRadiance(vec3 d, bool skipSummed) {
    vec2 uv = directionToEquirectUv(iblLookupDirection(d, push.ibl.rotation), 0.0f);
    ivec2 size = textureSize(referenceEquirect, 0);
    vec4 texel = texelFetch(referenceEquirect, clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1), 0);
    return skipSummed ? texel.rgb * texel.a : texel.rgb;
}

// Ground truth: the reflectance equation of the forward pass's BRDF (single scattering: Cook-Torrance
// GGX with height-correlated Smith visibility and Schlick Fresnel, Lambert weighted by
// (1 − F)(1 − metallic)) against the environment's texels. The brightest texels (a sun, lamps) are
// summed — no sampler finds a 0.5° sun — each as k × k sub-texels with their exact solid angles, k
// chosen so a sub-texel is at most half the specular lobe's width; the rest is integrated by Monte
// Carlo: cosine samples for the diffuse lobe, GGX half-vector samples for the specular one, over a
// per-pixel rotated Hammersley set. When the lobe would need more than kMaxSubdivision (many bright
// texels: large lamps) the specular lobe samples the whole map instead — a lobe that narrow finds
// large bright regions by itself. `pixel` (window coordinates) rotates the sample set per pixel.
vec3 referenceImageBasedLight(Surface s, vec2 pixel) {
    vec3 n = s.normal;
    vec3 v = s.v;
    vec3 baseColor = s.baseColor;
    float metallic = s.metallic;
    float alpha = s.roughness * s.roughness;
    float NoV = clamp(dot(n, v), CANDELA_MIN_NOV, 1.0f);
    vec3 f0 = s.f0;
    uint count = uint(referenceTexels[0].x);
    vec2 size = referenceTexels[0].yz;
    uint maxSubdivision = count <= 64u ? 16u : (count <= 512u ? 4u : 1u);
    float texelAngle = CANDELA_PI / size.y;
    uint subdivision = uint(clamp(ceil(2.0f * texelAngle / max(alpha, 1e-4f)), 1.0f, 1024.0f));
    bool sumSpecular = subdivision <= maxSubdivision;
    subdivision = min(subdivision, maxSubdivision);
    mat3 frame = basisAround(n);
    uvec2 p = uvec2(pixel);
    uint hash = (p.x * 1973u + p.y * 9277u + 26699u) * 0x9E3779B9u;
    vec2 shift = vec2(float(hash & 0xFFFFu), float(hash >> 16u)) / 65536.0f;
    vec3 specular = vec3(0.0f);
    vec3 diffuse = vec3(0.0f);
    for (uint i = 0u; i < kReferenceSamples; ++i) {
        vec2 xi = fract(hammersley(i, kReferenceSamples) + shift);
        vec3 h = frame * sampleGgxHalfVector(xi, alpha).xyz;
        float VoH = dot(v, h);
        vec3 l = 2.0f * VoH * h - v;
        float NoL = dot(n, l);
        if (NoL > 0.0f && VoH > 0.0f) {
            float NoH = max(dot(n, h), 1e-6f);
            specular += referenceRadiance(l, sumSpecular) * fresnelSchlick(VoH, f0) *
                        (visibilitySmithGgxCorrelated(NoV, NoL, alpha) * 4.0f * NoL * VoH / NoH);
        }
        vec3 ld = frame * sampleCosine(xi);
        vec3 hd = normalize(v + ld);
        diffuse += referenceRadiance(ld, true) * (vec3(1.0f) - fresnelSchlick(dot(v, hd), f0));
    }
    diffuse *= baseColor * (1.0f - metallic);
    vec3 sampled = (specular + diffuse) / float(kReferenceSamples);
    // Environment frame → world: the inverse rotation.
    vec4 inverseRotation = vec4(push.ibl.rotation.x, -push.ibl.rotation.y, 0.0f, 0.0f);
    vec3 summed = vec3(0.0f);
    float k = float(subdivision);
    for (uint i = 0u; i < count; ++i) {
        vec2 texel = referenceTexels[1u + 2u * i].xy;
        vec3 radiance = referenceTexels[2u + 2u * i].rgb;
        for (uint sy = 0u; sy < subdivision; ++sy) {
            float v0 = (texel.y + float(sy) / k) / size.y, v1 = (texel.y + float(sy + 1u) / k) / size.y;
            float solidAngle = (CANDELA_TWO_PI / (size.x * k)) * (cos(CANDELA_PI * v0) - cos(CANDELA_PI * v1));
            for (uint sx = 0u; sx < subdivision; ++sx) {
                vec2 uv = vec2((texel.x + (float(sx) + 0.5f) / k) / size.x, 0.5f * (v0 + v1));
                vec3 l = iblLookupDirection(equirectUvToDirection(uv, 0.0f), inverseRotation);
                float NoL = dot(n, l);
                if (NoL <= 0.0f) continue;
                vec3 h = normalize(v + l);
                vec3 F = fresnelSchlick(dot(v, h), f0);
                vec3 f = (vec3(1.0f) - F) * (1.0f - metallic) * baseColor * (1.0f / CANDELA_PI);
                if (sumSpecular) {
                    vec3 nxh = cross(n, h);
                    float NoH = clamp(dot(n, h), 0.0f, 1.0f);
                    f += F * (distributionGgx(NoH, dot(nxh, nxh), alpha) * visibilitySmithGgxCorrelated(NoV, NoL, alpha));
                }
                summed += f * NoL * radiance * solidAngle;
            }
        }
    }
    return (sampled + summed) * push.ibl.intensity;  // no occlusion texture in the report's scene
}

#endif
