// The skin_morph pass's data layouts, shared by skin_morph.comp.glsl and the pass's C++ side.
#ifndef CANDELA_SHARED_SKIN_MORPH_H
#define CANDELA_SHARED_SKIN_MORPH_H

#include "shared/compat.h"

CANDELA_NAMESPACE_BEGIN

#define CANDELA_SKIN_MORPH_GROUP_SIZE 64
// A vertex (scene::Vertex) in floats: position 3, normal 3, tangent 4, uv0 2, uv1 2, color 4.
#define CANDELA_VERTEX_FLOATS 18

// Push constants of one dispatch: one deformed draw (std430).
struct SkinMorphPush {
    uint sourceFirstVertex;    // the draw's vertex range in the scene's vertex buffer
    uint vertexCount;
    uint targetFirstVertex;    // where its deformed copy starts in the deformed-vertex buffer
    uint deltaBase;            // index of (target 0, vertex 0) of its deformation in the delta buffer
    uint activeBase;           // its non-zero morph weights: [activeBase, activeBase + activeCount)
    uint activeCount;
    uint jointBase;            // index of its skin's first joint matrix; only with influencesPerVertex > 0
    uint influenceBase;        // index of (vertex 0, influence 0) in the influence buffer
    uint influencesPerVertex;  // 0: not skinned (mesh space out)
    uint pad0;
    uint pad1;
    uint pad2;
};

// One non-zero morph weight of a draw in this frame.
struct ActiveMorphTarget {
    uint target;
    float weight;
};

CANDELA_NAMESPACE_END

#endif
