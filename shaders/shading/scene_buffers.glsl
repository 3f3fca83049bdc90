// The scene's storage blocks, declared once for every program that reads them: set 0's lights,
// draws and materials, and set 1's material layers (the layered programs'). C++ finds them by
// these block names (passes/drawing/scene_blocks.h). Each is a macro, written where a program
// declares its resources, so that a stage declares only the blocks it reads (a device need offer
// only 4 storage buffers per stage).
#ifndef CANDELA_SCENE_BUFFERS_GLSL
#define CANDELA_SCENE_BUFFERS_GLSL

#include "shared/scene_data.h"

// A read-only std430 block `Block` of `Element`s named `member`, at (set, binding).
#define CANDELA_SCENE_BLOCK(setIndex, bindingIndex, Block, Element, member) \
    layout(std430, set = setIndex, binding = bindingIndex) readonly buffer Block { Element member[]; };
#define CANDELA_LIGHTS_BLOCK CANDELA_SCENE_BLOCK(0, 0, Lights, LightData, lights)
#define CANDELA_DRAWS_BLOCK CANDELA_SCENE_BLOCK(0, 1, Draws, DrawData, draws)
#define CANDELA_MATERIALS_BLOCK CANDELA_SCENE_BLOCK(0, 2, Materials, MaterialData, materials)
#define CANDELA_MATERIAL_LAYERS_BLOCK CANDELA_SCENE_BLOCK(1, 5, MaterialLayers, MaterialLayerData, layers)

#endif
