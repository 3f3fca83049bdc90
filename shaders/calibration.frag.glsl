#version 460
#extension GL_GOOGLE_include_directive : require
// The calibration pass: a fixed amount of typical shading work per pixel, run in the same process
// as every benchmark so figures can be given as ratios to it (absolute times on a shared CPU vary
// by 2×). Fixed once and never tuned: GGX for 4 point lights plus the three image-based-lighting
// lookups (irradiance cube, prefiltered cube with textureLod, 2D BRDF LUT) on small constant
// textures, writing RGBA16F.
#include "shared/brdf.h"

layout(set = 0, binding = 0) uniform samplerCube irradianceMap;
layout(set = 0, binding = 1) uniform samplerCube prefilteredMap;
layout(set = 0, binding = 2) uniform sampler2D brdfLut;

layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
    // A sphere-like normal field over the screen and a fixed material that varies with position.
    vec2 p = inUv * 2.0f - 1.0f;
    vec3 n = normalize(vec3(p, sqrt(max(1.0f - dot(p, p) * 0.5f, 0.05f))));
    vec3 v = vec3(0.0f, 0.0f, 1.0f);
    vec3 position = vec3(p * 4.0f, 0.0f);
    float roughness = inUv.x;
    float metallic = inUv.y;
    vec3 baseColor = vec3(0.8f, 0.5f, 0.3f);
    vec3 lightPositions[4] = vec3[](vec3(-10.0f, 10.0f, 10.0f), vec3(10.0f, 10.0f, 10.0f),
                                    vec3(-10.0f, -10.0f, 10.0f), vec3(10.0f, -10.0f, 10.0f));
    vec3 color = vec3(0.0f);
    for (int i = 0; i < 4; ++i) {
        vec3 toLight = lightPositions[i] - position;
        float d2 = dot(toLight, toLight);
        color += brdfTimesCosine(n, v, toLight * inversesqrt(d2), baseColor, metallic, roughness, CANDELA_SHADING_PBR) *
                 (300.0f / d2);
    }
    float NoV = max(dot(n, v), 1e-4f);
    vec3 r = reflect(-v, n);
    vec3 f0 = mix(vec3(0.04f), baseColor, metallic);
    vec2 ab = texture(brdfLut, vec2(NoV, roughness)).rg;
    vec3 specular = textureLod(prefilteredMap, r, roughness * 4.0f).rgb * (f0 * ab.x + ab.y);
    vec3 diffuse = texture(irradianceMap, n).rgb * baseColor * (1.0f - metallic);
    outColor = vec4(color + specular + diffuse, 1.0f);
}
