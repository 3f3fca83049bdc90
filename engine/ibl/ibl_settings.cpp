#include "ibl/ibl_settings.h"

#include "core/errors.h"

#include <algorithm>
#include <bit>

namespace candela::ibl {

namespace {
void requirePowerOfTwo(const char* name, uint32_t value, uint32_t min, uint32_t max) {
    if (!std::has_single_bit(value) || value < min || value > max)
        throw UserError(std::string(name) + " " + std::to_string(value) + ": must be a power of two from " +
                        std::to_string(min) + " to " + std::to_string(max));
}
void requireRange(const char* name, uint32_t value, uint32_t min, uint32_t max) {
    if (value < min || value > max)
        throw UserError(std::string(name) + " " + std::to_string(value) + ": must be from " + std::to_string(min) +
                        " to " + std::to_string(max));
}
}  // namespace

void IblQuality::validate() const {
    requirePowerOfTwo("--ibl-cube-size", cubeSize, 16, 2048);
    requireRange("--ibl-levels", specularLevels, 2, 16);
    requireRange("--ibl-prefilter-samples", prefilterSamples, 1, 65536);
    requirePowerOfTwo("--ibl-sh-size", shSourceSize, 1, cubeSize);
    requirePowerOfTwo("--ibl-irradiance-size", irradianceSize, 1, 512);
    requireRange("--ibl-bright-texels", brightTexels, 0, 65536);
    requireRange("--ibl-irradiance-samples", irradianceSamples, 1, 65536);
    requireRange("--ibl-lut-size", lutSize, 2, 1024);
    requireRange("--ibl-lut-samples", lutSamples, 1, 65536);
    if (!(lodBias >= -4.0f && lodBias <= 4.0f))
        throw UserError("--ibl-lod-bias " + std::to_string(lodBias) + ": must be from -4 to 4");
}

uint32_t IblQuality::levels() const {
    return std::min(specularLevels, static_cast<uint32_t>(std::bit_width(cubeSize)));
}

std::string IblQuality::lutCanonical() const {
    return "lut=" + std::to_string(lutSize) + "x" + std::to_string(lutSamples);
}

std::string IblQuality::canonical() const {
    std::string irradianceText = irradiance == IrradianceMode::Sh9
                                     ? "sh9:" + std::to_string(shSourceSize)
                                     : "cube:" + std::to_string(irradianceSize) + "x" + std::to_string(irradianceSamples);
    // v3: the precompute reads the environment in half floats (scaled by a power of two).
    // v4: bright texels summed explicitly.
    return "v4 cube=" + std::to_string(cubeSize) + " levels=" + std::to_string(levels()) +
           " prefilter=" + std::to_string(prefilterSamples) +
           (filteredSampling ? ":bias" + std::to_string(lodBias).substr(0, 5) : ":unfiltered") +
           " bright=" + std::to_string(brightTexels) + " irradiance=" + irradianceText + " " + lutCanonical() +
           (sheen ? " sheen" : "") +
           (equirectMaxSize ? " equirect<=" + std::to_string(equirectMaxSize) : "");
}

}  // namespace candela::ibl
