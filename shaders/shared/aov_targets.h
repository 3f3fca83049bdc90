// The per-pixel outputs' targets (docs/outputs.md): the colour attachments of the aov pass (the
// fragment output location aov.frag.glsl compiles each at; a frame's variant packs the ones it asks
// for), read by GLSL (aov.frag.glsl) and C++ (the pass's
// formats, options/pixel_output.h's table of which output lies in which target's channels).
#ifndef CANDELA_SHARED_AOV_TARGETS_H
#define CANDELA_SHARED_AOV_TARGETS_H

#define CANDELA_AOV_VIEW_DEPTH 0          // R32F: distance along the view axis (world units, metres)
#define CANDELA_AOV_NORMAL 1              // RGBA32F: the world-space shading normal (xyz)
#define CANDELA_AOV_BASE_COLOR 2          // RGBA16F: linear base colour (rgb), alpha (a)
#define CANDELA_AOV_METALLIC_ROUGHNESS 3  // RG16F: metallic, perceptual roughness
#define CANDELA_AOV_EMISSIVE 4            // RGBA16F: emitted radiance factor × strength × texture (rgb)
#define CANDELA_AOV_IDS 5                 // RGBA32UI: glTF node, mesh, primitive, material
#define CANDELA_AOV_INSTANCE 6            // R32UI: EXT_mesh_gpu_instancing instance
#define CANDELA_AOV_TARGET_COUNT 7
// Not a colour target: the pass's own reverse-Z depth attachment, read back as the clip depth.
#define CANDELA_AOV_CLIP_DEPTH 7

#endif
