#pragma once
// What a frame draws and how, chosen per frame (RenderSettings): which draws and levels of detail
// it submits and how it shades. Plain data, no Vulkan.

#include <cstdint>

namespace candela::options {

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

}  // namespace candela::options
