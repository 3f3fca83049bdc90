#pragma once
// PosedSummary: what a frame's pose animates besides its nodes (KHR_animation_pointer), as data —
// the materials, lights and cameras with animated properties and the per-frame buffers the CPU
// writes for them. Made by FrameBuilder, kept with the frame (Renderer::lastPosed); tests assert
// its fields and explainPosed puts it into the --explain line. Pure: no Vulkan.

#include <cstdint>
#include <string>

namespace candela {

struct PosedSummary {
    uint32_t materials = 0;       // materials with animated properties: written to posed_materials
    bool materialLayers = false;  // ... and their layer data to posed_material_layers
    uint32_t lights = 0;          // lights with animated properties
    bool lightsWritten = false;   // posed_lights written (false: the scene's lights are not drawn)
    uint32_t cameras = 0;         // glTF cameras with animated properties (a view that follows one moves)
    bool empty() const { return materials == 0 && lights == 0 && cameras == 0; }
    bool operator==(const PosedSummary&) const = default;
};

// "animated properties (KHR_animation_pointer), written by the CPU per frame: N materials
// (posed_materials[, posed_material_layers]), N lights (posed_lights | not drawn: --scene-lights
// off), N cameras (the view of a glTF camera follows)", naming only what animates; "" when nothing does.
std::string explainPosed(const PosedSummary& summary);

}  // namespace candela
