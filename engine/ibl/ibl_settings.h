#pragma once
// Settings of image-based lighting. IblQuality decides what the precompute passes compute (a change
// reruns them, and it is part of the on-disk cache key); IblLook only changes how the maps are read
// at shading time (rotation, intensity, skybox), so changing it reruns nothing. Pure data.

#include "core/name_table.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace candela::ibl {

enum class IrradianceMode : uint8_t { Sh9, Cube };

// The modes' names: the one table that --irradiance and the ibl-report tables read.
inline constexpr std::pair<IrradianceMode, const char*> kIrradianceModeNames[] = {{IrradianceMode::Sh9, "sh9"},
                                                                                   {IrradianceMode::Cube, "cube"}};

// The mode named `name` in kIrradianceModeNames; nullopt for anything else.
constexpr std::optional<IrradianceMode> parseIrradianceMode(std::string_view name) {
    return valueNamed(kIrradianceModeNames, name);
}

constexpr const char* irradianceModeName(IrradianceMode mode) { return nameOf(kIrradianceModeNames, mode); }

struct IblQuality {
    uint32_t cubeSize = 256;          // face size of the float environment cube and of specular mip 0 (2^k, 16..2048)
    uint32_t specularLevels = 8;      // roughness levels 0, 1/(L−1) … 1 (at most log2(cubeSize) + 1)
    // GGX samples per texel of specular mip 1 (roughness 1/(levels−1)); each coarser mip, with 4×
    // fewer texels, takes 4× more (at most 4096), so every level costs the same.
    uint32_t prefilterSamples = 64;
    // Filtered importance sampling (each sample reads the source mip matching its solid angle);
    // false: plain importance sampling from mip 0, the brute-force comparison of `ibl-report`.
    bool filteredSampling = true;
    // Added to the filtered-importance-sampling lod (Křivánek & Colbert: +1). Larger: less noise
    // from small bright sources, more blur (a smooth gradient regresses toward its mean).
    float lodBias = 0.5f;
    // At most this many of the environment's brightest texels (those over kBrightTexelFactor × its
    // mean luminance: a sun) are summed explicitly by every filter pass instead of being sampled
    // (engine/ibl_maps/bright_texels.h); 0: everything is sampled. "bright=N" in the canonical text.
    uint32_t brightTexels = 256;
    // The cube: with the bright texels summed it converges at a few dozen samples, while SH9's order-2
    // truncation of a sun stays the largest visible error of the maps (docs/ibl.md, "Defaults and why").
    IrradianceMode irradiance = IrradianceMode::Cube;
    uint32_t shSourceSize = 32;       // face size of the cube mip projected onto SH9 (2^k ≤ cubeSize)
    uint32_t irradianceSize = 32;     // face size of the irradiance cube (cube mode)
    uint32_t irradianceSamples = 256; // cosine samples per irradiance texel (cube mode)
    uint32_t lutSize = 128;           // BRDF LUT is lutSize² (≥ 2)
    uint32_t lutSamples = 256;        // visible-normal samples per LUT texel
    // 0: the environment at its own size; else its equirect is halved (2×2 box) until it is at
    // most this wide and high before the precompute reads it (the memory fallback, a device's
    // maxImageDimension2D). "equirect<=N" in the canonical text.
    uint32_t equirectMaxSize = 0;
    // The Charlie-prefiltered cube for KHR_materials_sheen ("sheen" in the canonical text). Not a
    // user setting: the renderer asks for it when the scene has a sheen material.
    bool sheen = false;

    // Throws UserError naming the first invalid member ("--ibl-cube-size 100: must be a power of two …").
    void validate() const;
    // Specular mips actually used: min(specularLevels, log2(cubeSize) + 1).
    uint32_t levels() const;
    // The canonical text of every member (the cache key's settings part), e.g.
    // "v4 cube=256 levels=8 prefilter=64:bias0.500 bright=256 irradiance=cube:32x256 lut=128x256". Members that the mode does
    // not use are left out, so they do not split the cache.
    std::string canonical() const;
    // The part that only the BRDF LUT depends on.
    std::string lutCanonical() const;
    bool operator==(const IblQuality&) const = default;
};

struct IblLook {
    float rotationDegrees = 0.0f;  // turns the environment about +Y (shared/environment.h)
    float intensity = 1.0f;        // scales the environment's radiance (lighting and skybox)
    bool skybox = true;            // draw the environment behind the scene
    float skyboxBlur = 0.0f;       // 0 = sharp … 1 = the roughness-1 mip
    bool multiscatter = true;      // Fdez-Agüera energy compensation
    // > 0: shade with the ground truth (the reflectance equation integrated per pixel with this many
    // samples per lobe) instead of the split sum; for `ibl-report`. Slow.
    uint32_t referenceSamples = 0;
    bool operator==(const IblLook&) const = default;
};

}  // namespace candela::ibl
