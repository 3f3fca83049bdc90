#pragma once
// The image-based-lighting maps as one frame's graph knows them: handles of the imported maps (or,
// in a frame that computes them, of the versions its precompute passes write). ibl_maps::IblMaps makes
// them (IblMaps::addToGraph); the forward and skybox passes declare reads of the ones they use and
// resolve them through their PassContext, so a map replaced between frames is never bound stale.

#include "graph/graph_types.h"

namespace candela::passes {

struct IblHandles {
    graph::TextureId specular;        // RGBA16F cube, mip m = GGX-prefiltered at roughness m / (levels − 1)
    graph::TextureId irradianceCube;  // RGBA16F cube of E(n)/π — irradiance "cube" mode only, else invalid
    graph::BufferId sh;               // 9 × vec4 SH coefficients of E(n)/π — "sh9" mode only, else invalid
    graph::TextureId lut;             // RG16F split-sum BRDF LUT
    // RGBA16F cube, mip m Charlie-prefiltered at sheen roughness m / (levels − 1) (KHR_materials_sheen);
    // invalid unless the quality asked for it (IblQuality::sheen).
    graph::TextureId sheen;
    // The ground truth of `ibl-report` (IblMaps::setReferenceEnvironment): the environment as an
    // RGBA32F equirectangular image and its brightest texels; invalid when not set.
    graph::TextureId referenceEquirect;
    graph::BufferId referenceTexels;
};

}  // namespace candela::passes
