#version 460
// Encodes the HDR image for an 8-bit output: clamps to [0,1]. The target's _SRGB format applies
// the sRGB transfer function on write.
layout(set = 0, binding = 0) uniform sampler2D hdrImage;

layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
    vec3 hdr = texelFetch(hdrImage, ivec2(gl_FragCoord.xy), 0).rgb;
    outColor = vec4(clamp(hdr, vec3(0.0f), vec3(1.0f)), 1.0f);
}
