#version 460
#extension GL_GOOGLE_include_directive : require
// ibl_cube_downsample.comp and its variants (builtin_shaders.txt: they define
// CANDELA_FLOAT_CUBE_FORMAT, the storage format qualifier).
// IBL precompute, step 2: one mip of the float cube map from the one above (2×2 box filter, faces
// independent). Dispatched once per mip; the pass orders the dispatches with barriers.
#include "shared/ibl.h"

layout(local_size_x = CANDELA_IBL_GROUP, local_size_y = CANDELA_IBL_GROUP) in;

layout(set = 0, binding = 0, CANDELA_FLOAT_CUBE_FORMAT) uniform readonly image2DArray srcMip;
layout(set = 0, binding = 1, CANDELA_FLOAT_CUBE_FORMAT) uniform writeonly image2DArray dstMip;

layout(push_constant) uniform Push {
    IblDownsamplePush push;
};

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.dstFaceSize || id.y >= push.dstFaceSize) return;
    ivec3 s = ivec3(id.xy * 2u, id.z);
    vec4 sum = imageLoad(srcMip, s) + imageLoad(srcMip, s + ivec3(1, 0, 0)) + imageLoad(srcMip, s + ivec3(0, 1, 0)) +
               imageLoad(srcMip, s + ivec3(1, 1, 0));
    imageStore(dstMip, ivec3(id), sum * 0.25f);
}
