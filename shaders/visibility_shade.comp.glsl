#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility path's compute shading (docs/shading-paths.md), compiled as visibility_shade.comp
// (core materials) and visibility_shade_layers.comp (CANDELA_MATERIAL_LAYERS; builtin_shaders.txt):
// one workgroup per screen tile the classification listed for this dispatch's list (push.counts.z:
// one shading variant and one set of material textures); each invocation shades its pixel if the
// visibility image says the pixel shows a draw of that list.
// It fetches the triangle (the level of detail's indices, the deformed vertices of skinned and
// morphed draws, the instance's transform), computes perspective-correct barycentrics and their
// change over one pixel, interpolates the attributes, and calls the shading the forward fragment
// stage calls (shading/shade.glsl) with textures sampled at explicit gradients.
#define CANDELA_VISIBILITY_SHADING
#include "shading/resources.glsl"
#include "shared/skin_morph.h"
#include "shared/visibility.h"

layout(local_size_x_id = CANDELA_SPEC_TILE_X, local_size_y_id = CANDELA_SPEC_TILE_Y) in;

// The dispatch's own constants (shared/specialization_ids.h): whether the frame has deformed
// vertices (else every draw reads the scene's), and which texture slots its texture set fills
// (bit per CANDELA_TEX_* / CANDELA_LAYER_TEX_* slot; the others hold the 1×1 white default, read as
// the constant it is, with no coordinates or gradients computed for it).
layout(constant_id = CANDELA_SPEC_DEFORMED) const bool kDeformed = true;
layout(constant_id = CANDELA_SPEC_CORE_TEXTURES) const uint kCoreTextures = 0xffffffffu;
layout(constant_id = CANDELA_SPEC_LAYER_TEXTURES) const uint kLayerTextures = 0xffffffffu;

// Set 4: what the visibility pass and the classification produced, and the geometry.
#ifdef CANDELA_VISIBILITY_MSAA
// With MSAA (visibility_shade*_msaa.comp) a pixel's samples may show several triangles. The
// dispatch of "distinct" k shades, in each pixel of its list, the k-th distinct triangle its samples
// show (in sample order, background skipped), weighted by the share of samples showing it: k = 0
// stores (every covered pixel has a first), k > 0 adds to it (only pixels on triangle edges have a
// second) — the resolve is part of shading, and MSAA costs only the edges' extra triangles.
layout(constant_id = CANDELA_SPEC_DISTINCT) const uint kDistinct = 0u;
layout(constant_id = CANDELA_SPEC_SAMPLES) const int kSamples = 4;
layout(set = 4, binding = 0) uniform usampler2DMS visibility;  // per sample (draw entry + 1, primitive); 0: none
layout(set = 4, binding = 1, rgba16f) uniform image2D shaded;
#else
layout(set = 4, binding = 0) uniform usampler2D visibility;  // (draw entry + 1, primitive); 0: none
layout(set = 4, binding = 1, rgba16f) uniform writeonly image2D shaded;
#endif
layout(std430, set = 4, binding = 2) readonly buffer Vertices {
    float vertexFloats[];  // the scene's, CANDELA_VERTEX_FLOATS per vertex (scene::Vertex)
};
layout(std430, set = 4, binding = 3) readonly buffer DeformedVertices {
    float deformedFloats[];  // this frame's skin_morph output (the scene's vertices when none)
};
layout(std430, set = 4, binding = 4) readonly buffer Indices {
    uint indices[];
};
layout(std430, set = 4, binding = 5) readonly buffer VisibilityDraws {
    VisibilityDraw visibilityDraws[];
};
layout(std430, set = 4, binding = 6) readonly buffer TileLists {
    uint tileLists[];  // per list, frame.extent.w entries: tile x | tile y << 16
};
layout(std430, set = 4, binding = 7) readonly buffer Frame {
    VisibilityFrame frame;
};

// Material textures at the gradients compute shading derived (shading/material_eval.glsl reads
// them through these). The dispatch's material set (1) is bound uniformly: every pixel it shades
// has the same textures.
#define CANDELA_CORE_TEXTURE(inputs, field, slot)                                                                  \
    ((kCoreTextures & (1u << (slot))) != 0u                                                                        \
         ? textureGrad(field##Texture, (inputs).uv[slot], (inputs).uvDx[slot], (inputs).uvDy[slot])                \
         : vec4(1.0f))
#define CANDELA_LAYER_TEXTURE(inputs, field, slot)                                                                 \
    ((kLayerTextures & (1u << (slot))) != 0u                                                                       \
         ? textureGrad(field##Texture, (inputs).layerUv[slot], (inputs).layerUvDx[slot], (inputs).layerUvDy[slot]) \
         : vec4(1.0f))

#include "shading/shade.glsl"

// One vertex of the scene's layout.
struct Vertex {
    vec3 position;
    vec3 normal;
    vec4 tangent;
    vec2 uv0;
    vec2 uv1;
    vec4 color;
};

float vertexFloat(bool rest, uint i) { return !kDeformed || rest ? vertexFloats[i] : deformedFloats[i]; }

Vertex fetchVertex(VisibilityDraw draw, uint index) {
    bool rest = draw.vertexOffset == CANDELA_REST_VERTICES;
    uint at = uint(rest ? int(index) : int(index) + draw.vertexOffset) * uint(CANDELA_VERTEX_FLOATS);
    float f[CANDELA_VERTEX_FLOATS];
    for (uint i = 0u; i < uint(CANDELA_VERTEX_FLOATS); ++i) f[i] = vertexFloat(rest, at + i);
    Vertex v;
    v.position = vec3(f[0], f[1], f[2]);
    v.normal = vec3(f[3], f[4], f[5]);
    v.tangent = vec4(f[6], f[7], f[8], f[9]);
    v.uv0 = vec2(f[10], f[11]);
    v.uv1 = vec2(f[12], f[13]);
    v.color = vec4(f[14], f[15], f[16], f[17]);
    return v;
}

// Perspective-correct barycentrics of the triangle with clip-space corners `clip` (the columns'
// x, y, w) at normalized device coordinates `ndc`. Homogeneous rasterization (Olano & Greer 1997):
// the point Σ λ_i c_i projects to ndc when M λ ∝ (ndc, 1), M = (c_0.xyw c_1.xyw c_2.xyw); so λ is
// M⁻¹ (ndc, 1) normalized to sum 1 — exact for corners behind the eye too, unlike barycentrics of
// the projected corners. As in the visibility buffer of Burns & Hunt 2013 and Schied & Dachsbacher
// 2015 (deferred attribute interpolation), the derivatives come from evaluating this at the
// neighbouring pixels rather than from a 2×2 quad.
vec3 barycentrics(mat3 inverseM, vec2 ndc) {
    vec3 l = inverseM * vec3(ndc, 1.0f);
    return l / (l.x + l.y + l.z);
}

vec2 mix3(vec2 a, vec2 b, vec2 c, vec3 l) { return a * l.x + b * l.y + c * l.z; }
vec3 mix3(vec3 a, vec3 b, vec3 c, vec3 l) { return a * l.x + b * l.y + c * l.z; }
vec4 mix3(vec4 a, vec4 b, vec4 c, vec3 l) { return a * l.x + b * l.y + c * l.z; }

// A slot's coordinates at the three points and the two differences.
void slotUv(UvTransform t, Vertex v0, Vertex v1, Vertex v2, vec3 l, vec3 lx, vec3 ly, out vec2 uv, out vec2 dx, out vec2 dy) {
    vec2 a = transformUv(t, v0.uv0, v0.uv1), b = transformUv(t, v1.uv0, v1.uv1), c = transformUv(t, v2.uv0, v2.uv1);
    uv = mix3(a, b, c, l);
    dx = mix3(a, b, c, lx) - uv;
    dy = mix3(a, b, c, ly) - uv;
}

// The unit interpolated normal at barycentrics `l` (normalMatrix applied), on the viewer's side
// for back faces; zero where it degenerates.
vec3 facedVertexNormal(mat3 normalMatrix, Vertex v0, Vertex v1, Vertex v2, vec3 l, bool frontFacing) {
    vec3 n = normalMatrix * mix3(v0.normal, v1.normal, v2.normal, l);
    if (dot(n, n) <= 1e-12f) return vec3(0.0f);
    return frontFacing ? normalize(n) : -normalize(n);
}

// What material evaluation reads at `pixel` of the primitive `primitive` of draw entry `entry`.
SurfaceInputs visibleInputs(uint entry, uint primitive, ivec2 pixel, ivec2 size) {
    VisibilityDraw vis = visibilityDraws[entry];
    DrawData draw = draws[entry];
    uint first = vis.firstIndex + 3u * primitive;
    Vertex v0 = fetchVertex(vis, indices[first]);
    Vertex v1 = fetchVertex(vis, indices[first + 1u]);
    Vertex v2 = fetchVertex(vis, indices[first + 2u]);
    vec3 w0 = (draw.world * vec4(v0.position, 1.0f)).xyz;
    vec3 w1 = (draw.world * vec4(v1.position, 1.0f)).xyz;
    vec3 w2 = (draw.world * vec4(v2.position, 1.0f)).xyz;
    vec4 c0 = push.viewProjection * vec4(w0, 1.0f);
    vec4 c1 = push.viewProjection * vec4(w1, 1.0f);
    vec4 c2 = push.viewProjection * vec4(w2, 1.0f);
    mat3 m = mat3(c0.xyw, c1.xyw, c2.xyw);
    mat3 inverseM = inverse(m);
    vec2 pixelNdc = 2.0f / vec2(size);
    vec2 ndc = (vec2(pixel) + 0.5f) * pixelNdc - 1.0f;
    vec3 l = barycentrics(inverseM, ndc);
    vec3 lx = barycentrics(inverseM, ndc + vec2(pixelNdc.x, 0.0f));
    vec3 ly = barycentrics(inverseM, ndc + vec2(0.0f, pixelNdc.y));

    SurfaceInputs inputs;
    inputs.draw = entry;
    inputs.eye = push.eye.xyz;
    inputs.position = mix3(w0, w1, w2, l);
    mat3 normalMatrix = mat3(draw.normalMatrix);
    inputs.normal = normalMatrix * mix3(v0.normal, v1.normal, v2.normal, l);
    vec4 tangent = mix3(v0.tangent, v1.tangent, v2.tangent, l);
    inputs.tangent = vec4(mat3(draw.world) * tangent.xyz, tangent.w);
    inputs.faceNormal = normalize(cross(w1 - w0, w2 - w0));
    // Vulkan's framebuffer y points down: a counter-clockwise (front) triangle has det(M) < 0 when
    // its corners are in front of the eye (M's determinant is their w product times twice the
    // signed area of the projection); a mirroring transform turns fronts clockwise.
    inputs.frontFacing = (determinant(m) < 0.0f) != (vis.flipWinding != 0u);
    inputs.color = mix3(v0.color, v1.color, v2.color, l);
    MaterialData material = materials[draw.material.x];
    for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot)
        if ((kCoreTextures & (1u << slot)) != 0u)
            slotUv(material.uv[slot], v0, v1, v2, l, lx, ly, inputs.uv[slot], inputs.uvDx[slot], inputs.uvDy[slot]);
#ifdef CANDELA_MATERIAL_LAYERS
    MaterialLayerData layer = layers[draw.material.x];
    for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot)
        if ((kLayerTextures & (1u << slot)) != 0u)
            slotUv(layer.uv[slot], v0, v1, v2, l, lx, ly, inputs.layerUv[slot], inputs.layerUvDx[slot], inputs.layerUvDy[slot]);
#endif
    inputs.normalChange = 0.0f;
    if (kSpecularAa) {
        // The faced normal's change over one pixel, as the forward stage's dFdx/dFdy of it.
        vec3 n = facedNormal(inputs);
        vec3 dx = facedVertexNormal(normalMatrix, v0, v1, v2, lx, inputs.frontFacing) - n;
        vec3 dy = facedVertexNormal(normalMatrix, v0, v1, v2, ly, inputs.frontFacing) - n;
        inputs.normalChange = dot(dx, dx) + dot(dy, dy);
    }
    return inputs;
}

// The shaded colour of `primitive` of draw entry `entry` at `pixel`.
vec4 shadeVisible(uint entry, uint primitive, ivec2 pixel, ivec2 size) {
    SurfaceInputs inputs = visibleInputs(entry, primitive, pixel, size);
    // Masked materials passed the alpha test in the visibility pass: covered, alpha 1.
    return shadeSurface(inputs, materialBaseColor(inputs), vec2(pixel) + 0.5f);
}

#ifdef CANDELA_VISIBILITY_MSAA
// The kDistinct-th distinct covered ID of `pixel`'s samples, and how many samples show it (0: none).
uvec2 distinctId(ivec2 pixel, out int count) {
    uvec2 ids[kSamples];
    for (int s = 0; s < kSamples; ++s) ids[s] = texelFetch(visibility, pixel, s).xy;
    uvec2 id = uvec2(0u);
    uint distinct = 0u;
    for (int s = 0; s < kSamples; ++s) {
        bool seen = ids[s].x == 0u;
        for (int t = 0; t < s; ++t) seen = seen || ids[t] == ids[s];
        if (!seen) {
            if (distinct == kDistinct) id = ids[s];
            ++distinct;
        }
    }
    count = 0;
    for (int s = 0; s < kSamples; ++s) count += id.x != 0u && ids[s] == id ? 1 : 0;
    return id;
}
#endif

void main() {
    uint tile = tileLists[push.counts.z * frame.extent.w + gl_WorkGroupID.x];
    // Unsigned, converted once: ivec2(gl_WorkGroupSize.xy) is a spec-constant IAdd that
    // SPIRV-Tools' spec-constant folding (run by the validation layer on every specialized module)
    // can rewrite to use constants declared after it — invalid SPIR-V, VUID 06719, when nothing else
    // in the module uses int 8 and int 1 earlier (docs/shading-paths.md).
    ivec2 pixel = ivec2(uvec2(tile & 0xffffu, tile >> 16u) * gl_WorkGroupSize.xy + gl_LocalInvocationID.xy);
    ivec2 size = ivec2(frame.extent.xy);
    if (any(greaterThanEqual(pixel, size))) return;
#ifdef CANDELA_VISIBILITY_MSAA
    int count;
    uvec2 id = distinctId(pixel, count);
    uint list = push.counts.z - kDistinct * frame.samples.y;
    if (id.x == 0u || visibilityDraws[id.x - 1u].list != list) return;
    vec4 color = shadeVisible(id.x - 1u, id.y, pixel, size) * (float(count) / float(kSamples));
    if (kDistinct > 0u) color += imageLoad(shaded, pixel);
    imageStore(shaded, pixel, color);
#else
    uvec2 id = texelFetch(visibility, pixel, 0).xy;
    if (id.x == 0u || visibilityDraws[id.x - 1u].list != push.counts.z) return;
    imageStore(shaded, pixel, shadeVisible(id.x - 1u, id.y, pixel, size));
#endif
}
