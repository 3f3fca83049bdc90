#pragma once
// What the forward pass draws and how, chosen per frame (RenderSettings): which draws and levels
// of detail it submits, how it shades, and what it recorded. Plain data, no Vulkan.

#include <cstdint>

namespace candela::passes {

// How the forward pass shades (docs/shading.md).
struct ShadingOptions {
    // Specular anti-aliasing: roughness widened by the normal's change across the pixel and by
    // what a normal map's mip averaged away. Off by default: the quality report measured it adding
    // image and temporal error against a supersampled reference (docs/anti-aliasing.md).
    bool specularAntiAliasing = false;
};

// Which draws and which of their levels of detail a frame submits (docs/geometry.md).
struct DrawSelection {
    // Leave out draws whose world bounds lie outside the view frustum.
    bool frustumCulling = true;
    // Draw each mesh at the coarsest level of detail whose error covers at most this many
    // pixels on screen; 0: full detail. The default is the knee of the quality report's error
    // against frame time (docs/anti-aliasing.md).
    static constexpr float kDefaultLodErrorPixels = 0.5f;
    float lodErrorPixels = kDefaultLodErrorPixels;
};

// What the last frame drew: draws and triangles of the scene (visible ones, each instance
// counted) against those submitted, and the state changes recorded to draw them.
struct DrawStats {
    uint32_t sceneDraws = 0, submittedDraws = 0, culledDraws = 0;
    uint32_t coarserDraws = 0;  // submitted at a level of detail beyond the full one
    uint64_t sceneTriangles = 0, submittedTriangles = 0;
    uint32_t pipelineBinds = 0, descriptorBinds = 0, dynamicStates = 0, bufferBinds = 0;
    uint32_t stateChanges() const { return pipelineBinds + descriptorBinds + dynamicStates + bufferBinds; }
};

}  // namespace candela::passes
