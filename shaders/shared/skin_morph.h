// The skin_morph pass's data layouts, shared by skin_morph.comp.glsl and the pass's C++ side.
#ifndef CANDELA_SHARED_SKIN_MORPH_H
#define CANDELA_SHARED_SKIN_MORPH_H

#include "shared/compat.h"

CANDELA_NAMESPACE_BEGIN

#define CANDELA_SKIN_MORPH_GROUP_SIZE 64
// A vertex (scene::Vertex) in floats: position 3, normal 3, tangent 4, uv0 2, uv1 2, color 4.
#define CANDELA_VERTEX_FLOATS 18

// The words of one vertex's record in the scene's deformation buffer (GpuScene::deformationBuffer):
// its skin influences, 2 words each (joint index, weight bits), then its morph targets' deltas,
// CANDELA_MORPH_DELTA_WORDS each (position, normal, tangent, uv, color: vec4s).
#define CANDELA_INFLUENCE_WORDS 2
#define CANDELA_MORPH_DELTA_WORDS 20
// A joint matrix in the frame buffer: 16 floats, column-major.
#define CANDELA_JOINT_WORDS 16
// An ActiveMorphTarget in the frame buffer: target index, weight bits.
#define CANDELA_ACTIVE_TARGET_WORDS 2

// Push constants of one dispatch: a run of vertices of one deformed draw (std430). Indices are
// relative to the buffer ranges the dispatch's descriptor set binds
// (passes/deform/skin_morph_dispatch.h).
struct SkinMorphPush {
    uint vertexCount;          // vertices of this dispatch
    uint groupsX;              // its group count in X: vertex = (group.y * groupsX + group.x) * group size + local
    uint sourceFloat;          // BaseVertices float of its first vertex
    uint targetFloat;          // Deformed float of its first vertex
    uint recordWord;           // Deformation word of its first vertex's record
    uint recordWords;          // words per record: influences and deltas of one vertex
    uint deltaWord;            // where the deltas start in a record
    uint influencesPerVertex;  // 0: not skinned (mesh space out)
    uint jointWord;            // FrameData word of its skin's first joint matrix; only when skinned
    uint activeWord;           // FrameData word of its first non-zero morph weight
    uint activeCount;          // its non-zero morph weights
    uint pad0;
};

// One non-zero morph weight of a draw in this frame.
struct ActiveMorphTarget {
    uint target;
    float weight;
};

CANDELA_NAMESPACE_END

#endif
