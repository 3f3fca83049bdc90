#pragma once
// What Candela chooses from a device's capabilities (DeviceCaps, possibly narrowed by a profile):
// the formats of the maps it computes, with the fallback a device takes when it lacks a format
// feature; what a device must have at all; and whether a program's descriptors fit the per-stage
// limits. Pure functions, unit-tested on the caps of the device profiles.

#include "shader/reflection.h"
#include "vk/device_caps.h"

#include <string>
#include <vector>

namespace candela::vk {

struct DeviceChoices {
    // The environment's float cube (written by compute, sampled with linear filtering by the
    // prefilter): RGBA32F, or RGBA16F where RGBA32F is not linearly filterable.
    VkFormat floatCube = VK_FORMAT_R32G32B32A32_SFLOAT;
    // The sheen albedo LUT (written by compute, sampled with linear filtering): R32F, or RGBA16F
    // where R32F is not linearly filterable.
    VkFormat sheenLut = VK_FORMAT_R32_SFLOAT;
    // The BRDF LUT (written by compute, sampled with linear filtering): RG16F, or RGBA16F where
    // RG16F cannot be a storage image (an extended storage format).
    VkFormat brdfLut = VK_FORMAT_R16G16_SFLOAT;
    // Whether the layered forward program (forward_layers.*: every layer's textures and maps, 25
    // samplers and 4 storage buffers in the fragment stage) exceeds the per-stage limits, so each
    // layered variant is specialized at load to declare only its layers' descriptors
    // (vk::ProgramSpecialization). A material whose layers still exceed them is refused by name.
    bool specializeLayeredProgram = false;
    // Why the visibility shading path (docs/shading-paths.md) cannot run here ("" if it can): it
    // stores gl_PrimitiveID from the fragment stage (geometryShader), renders and samples
    // R32G32_UINT, and its compute shading binds 5 sets, ~10 storage buffers and the layered
    // program's 19 material textures besides the maps. Frames then take the forward path.
    std::string visibilityUnsupported;
    // Whether a cube map written by a compute shader must be bound to a draw before a compute
    // shader samples it with linear filtering. SwiftShader keeps a one-texel border around each
    // face for seamless filtering and refreshes it only when a draw is about to sample the image;
    // a compute shader filtering across a face edge otherwise reads stale borders
    // (docs/devices.md). The IBL precompute then draws once, rasterizing nothing, with the cube
    // bound (passes/ibl/ibl_cube_borders.h).
    bool cubeBordersNeedADraw = false;
    // One line per fallback taken ("BRDF LUT: R16G16B16A16_SFLOAT instead of R16G16_SFLOAT (no
    // STORAGE_IMAGE)"); empty when the device has everything.
    std::vector<std::string> fallbacks;
};

DeviceChoices chooseForDevice(const DeviceCaps& caps);

// Why a device cannot run Candela at all — a format feature or limit no fallback replaces — or ""
// if it can.
std::string missingCapability(const DeviceCaps& caps);

// Whether the descriptors and push constants of `bindings` fit the device's per-stage and
// per-pipeline limits: "" if they do, else one line naming the stage, the count and the limit.
std::string descriptorLimitViolation(const std::vector<shader::DescriptorBinding>& bindings, uint32_t pushConstantBytes,
                                     const DeviceCaps& caps);

}  // namespace candela::vk
