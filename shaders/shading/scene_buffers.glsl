// The scene's storage blocks, declared once for every program that reads them: set 0's lights,
// draws and materials, and set 1's material layers (the layered programs'). C++ finds them by
// these block names (passes/drawing/scene_blocks.h). Each is a macro, written where a program
// declares its resources, so that a stage declares only the blocks it reads (a device need offer
// only 4 storage buffers per stage).
#ifndef CANDELA_SCENE_BUFFERS_GLSL
#define CANDELA_SCENE_BUFFERS_GLSL

#include "shared/scene_data.h"

#define CANDELA_LIGHTS_BLOCK                                \
    layout(std430, set = 0, binding = 0) readonly buffer Lights { \
        LightData lights[];                                 \
    };
#define CANDELA_DRAWS_BLOCK                                \
    layout(std430, set = 0, binding = 1) readonly buffer Draws { \
        DrawData draws[];                                  \
    };
#define CANDELA_MATERIALS_BLOCK                                \
    layout(std430, set = 0, binding = 2) readonly buffer Materials { \
        MaterialData materials[];                              \
    };
#define CANDELA_MATERIAL_LAYERS_BLOCK                                \
    layout(std430, set = 1, binding = 5) readonly buffer MaterialLayers { \
        MaterialLayerData layers[];                                  \
    };

#endif
