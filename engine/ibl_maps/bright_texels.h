#pragma once
// The environment's bright texels, split off before filtering. Filtered importance sampling finds a
// small bright source (a 0.5° sun of 28,000) with one or two of its samples at most, so at the
// default sample counts every filtered map showed it as a blocky, speckled blob. So texels whose
// luminance is over a threshold are clamped to it in the float cube that the filter passes sample
// (ibl_cubemap.comp, iblClampLuminance in shaders/shared/ibl.h), and each filter pass adds their
// excess explicitly, as a point source at the texel's centre whose flux is the excess radiance ×
// the texel's solid angle: ibl_filter_cube.comp weighs it by the pass's normalised lobe
// (engine/passes/ibl/ibl_sample_tables.h lobeTable), ibl_irradiance_sh.comp projects it onto SH9. The
// sampled remainder is smooth and converges with few samples; the sun is summed, not sampled.
// The specular cube's mip 0 (the mirror and the skybox) keeps the texels as they are. Pure CPU.

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

namespace candela::ibl_maps {

// A texel is a bright-texel candidate when its luminance is over this multiple of the map's mean
// luminance (solid-angle weighted); the ground truth of `ibl-report` sums the same texels one by one.
inline constexpr double kBrightTexelFactor = 20.0;

struct BrightTexels {
    // Luminance above which texels are clamped, in the units of the values given to
    // findBrightTexels; infinity when none is split off.
    float threshold = std::numeric_limits<float>::infinity();
    // The storage buffer the filter passes read: [0] = (count, 0, 0, 0), then per texel
    // (direction in the environment's frame, 0) and (flux: excess radiance × solid angle, 0), the flux
    // in radiance units (the values divided by `scale`).
    std::vector<glm::vec4> buffer{glm::vec4(0.0f)};
    uint32_t count() const { return static_cast<uint32_t>((buffer.size() - 1) / 2); }
};

// kBrightTexelFactor × the solid-angle-weighted mean of `luminance(i)` over a `width` × `height`
// equirectangular map (texel i = y · width + x): the luminance above which a texel is a bright-texel
// candidate, for the filters' split (findBrightTexels) and for the ground truth's explicit sums
// (IblMaps::setReferenceEnvironment). Preconditions: width, height ≥ 1.
double brightCandidateLuminance(uint32_t width, uint32_t height, const std::function<double(size_t)>& luminance);

// The bright texels of an equirectangular map (rotation 0) given as `width` × `height` RGBA half-float
// texels (`rgba`, 4 each, alpha ignored: the texels the cubemap pass reads) that hold radiance × `scale`: those whose luminance is over
// kBrightTexelFactor × the mean, at most the `maxCount` brightest — the threshold then rises to the
// luminance of the brightest texel left out. maxCount 0 splits off nothing.
// Preconditions: rgba.size() == width × height × 4, width, height ≥ 1, scale > 0, values finite ≥ 0.
BrightTexels findBrightTexels(std::span<const uint16_t> rgba, uint32_t width, uint32_t height, float scale,
                              uint32_t maxCount);

}  // namespace candela::ibl_maps
