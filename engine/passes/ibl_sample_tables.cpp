#include "passes/ibl_sample_tables.h"

#include "shared/ibl.h"

namespace candela::passes {

using namespace shading;

namespace {
float texelSolidAngle(uint32_t faceSize) { return 4.0f * CANDELA_PI / (6.0f * float(faceSize) * float(faceSize)); }
}  // namespace

SampleTable prefilterSamples(float roughness, uint32_t count, uint32_t sourceFaceSize, uint32_t sourceMips,
                             bool filtered, float lodBias) {
    SampleTable table;
    const float alpha = roughness * roughness;
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec4 h = sampleGgxHalfVector(hammersley(i, count), alpha);
        // n = v: l = reflect(−n, h), n·l = 2 (n·h)² − 1, pdf(l) = D / 4.
        const float NoL = 2.0f * h.w - 1.0f;
        if (NoL <= 0.0f) continue;
        const glm::vec3 l(2.0f * h.z * h.x, 2.0f * h.z * h.y, NoL);
        const float pdf = ggxD(h.w, 1.0f - h.w, alpha) * 0.25f;
        const float lod = filtered ? filteredLod(pdf, count, texelSolidAngle(sourceFaceSize), float(sourceMips - 1), lodBias) : 0.0f;
        table.samples.emplace_back(glm::normalize(l), lod);
        table.totalWeight += NoL;
    }
    return table;
}

SampleTable irradianceSamples(uint32_t count, uint32_t sourceFaceSize, uint32_t sourceMips, bool filtered,
                              float lodBias) {
    SampleTable table;
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec3 l = sampleCosine(hammersley(i, count));
        const float pdf = l.z / CANDELA_PI;
        const float lod = filtered ? filteredLod(pdf, count, texelSolidAngle(sourceFaceSize), float(sourceMips - 1), lodBias) : 0.0f;
        table.samples.emplace_back(l, lod);
        table.totalWeight += 1.0f;
    }
    return table;
}

}  // namespace candela::passes
