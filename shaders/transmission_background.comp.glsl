#version 460
// The transmission background (passes/backdrop/transmission_background_pass.h), one mip per
// dispatch: mip 0 is the forward pass's opaque image, copied; mip m the 2×2 box of mip m − 1 — one
// bilinear tap at the centre of each destination texel, which for an even source is exactly the
// mean of its 2×2 block (for an odd one, a bilinear resampling). The pass orders the dispatches
// with barriers.

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2D source;  // one mip (or the opaque image), bilinear, clamped
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D destination;

layout(push_constant) uniform Push {
    uvec2 size;  // the destination's
} push;

void main() {
    uvec2 id = gl_GlobalInvocationID.xy;
    if (id.x >= push.size.x || id.y >= push.size.y) return;
    vec2 uv = (vec2(id) + 0.5f) / vec2(push.size);
    imageStore(destination, ivec2(id), textureLod(source, uv, 0.0f));
}
