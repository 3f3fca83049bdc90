#version 460
// The MSAA expand pass (passes/visibility/msaa_expand_pass.h): the resolved HDR texel, written to every
// sample of the pixel (the shader runs once per pixel).
layout(set = 0, binding = 0) uniform sampler2D hdrImage;

layout(location = 0) out vec4 outColor;

void main() { outColor = texelFetch(hdrImage, ivec2(gl_FragCoord.xy), 0); }
