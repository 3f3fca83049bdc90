#version 460
#extension GL_GOOGLE_include_directive : require
// Skybox: the environment behind the scene. Drawn as a full-screen triangle at the far plane
// (reverse-Z depth 0) with the depth test, so only pixels no opaque surface covered run it, and
// blended "under" what is there (colour += (1 − alpha) · sky), so blended surfaces keep their
// coverage. Reads the specular cube at the blur level's mip (0 = the environment itself).
#include "shared/ibl.h"

layout(set = 0, binding = 0) uniform samplerCube specularCube;

layout(push_constant) uniform Push {
    SkyboxPush push;
};

layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
    // A point on the near plane (reverse-Z: depth 1) through this pixel; the view ray is from the eye.
    vec4 nearPoint = push.inverseViewProjection * vec4(inUv * 2.0f - 1.0f, 1.0f, 1.0f);
    vec3 direction = normalize(nearPoint.xyz / nearPoint.w - push.eye.xyz);
    vec3 radiance = textureLod(specularCube, iblLookupDirection(direction, push.ibl.rotation), push.ibl.skyboxLod).rgb;
    outColor = vec4(min(radiance * push.ibl.intensity, vec3(60000.0f)), 1.0f);
}
