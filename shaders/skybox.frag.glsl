#version 460
#extension GL_GOOGLE_include_directive : require
// Skybox: the environment behind the scene. Drawn as a full-screen triangle at the far plane
// (reverse-Z depth 0) with the depth test, so only pixels no opaque surface covered run it, and
// blended "under" what is there (colour += (1 − alpha) · sky), so blended surfaces keep their
// coverage. Reads the specular cube at the blur level's mip (shared/sky.glsl).
#include "shared/ibl.h"

layout(set = 0, binding = 0) uniform samplerCube specularCube;

layout(push_constant) uniform Push {
    SkyboxPush push;
};

#include "shared/sky.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(skyRadiance(push.rays, gl_FragCoord.xy, push.ibl.skyboxLod, push.ibl.intensity), 1.0f);
}
