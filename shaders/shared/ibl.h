// Image-based lighting, shared by the precompute compute shaders, the forward and skybox shaders and
// the C++ side (push-constant structs, CPU tests of the shading algebra). A double-precision
// reference of the integrals lives in engine/reports/ibl_reference.h, written independently.
//
// Maps (all in the environment's own frame, rotation 0; lookups turn world directions by the
// environment rotation first, see iblLookupDirection):
//   specular cube   RGBA16F, mip m holds the GGX-prefiltered radiance for perceptual roughness
//                   m / (levels − 1) (split-sum first term, n = v = r); mip 0 is the environment itself
//   irradiance      cosine-weighted average radiance E(n)/π, as 9 SH coefficients (already convolved
//                   with the clamped cosine) or as a small RGBA16F cube
//   BRDF LUT        RG16F, u = N·V, v = perceptual roughness, both sampled at texel centres from 0 to 1
//                   inclusive; R = A, G = B of the split sum: single-scattering albedo E_ss = f0·A + B,
//                   and A + B is the directional albedo of a white metal, E(μ), which carries the
//                   multiple-scattering compensation.
#ifndef CANDELA_SHARED_IBL_H
#define CANDELA_SHARED_IBL_H

#include "shared/brdf.h"
#include "shared/compat.h"
#include "shared/sky_rays.h"

CANDELA_NAMESPACE_BEGIN

#ifndef CANDELA_PI
#define CANDELA_PI 3.14159265358979f
#endif
#define CANDELA_HALF_MAX 65504.0f
#define CANDELA_IBL_GROUP 8u       // 8×8 invocations per workgroup in the per-texel passes
#define CANDELA_IBL_SH_GROUP 64u   // invocations of the single SH-projection workgroup

// ---- Bright texels (engine/ibl_maps/bright_texels.h) ----

// Rec. 709 luminance, the measure of a texel's brightness for the bright-texel split.
CANDELA_FN float iblLuminance(vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// `radiance` scaled down so that its luminance is at most `threshold` (hue kept); the excess,
// radiance − iblClampLuminance(radiance, threshold), is what the bright-texel list carries.
CANDELA_FN vec3 iblClampLuminance(vec3 radiance, float threshold) {
    float y = iblLuminance(radiance);
    return y > threshold ? radiance * (threshold / y) : radiance;
}

// Entries of a filter lobe table (engine/passes/ibl/ibl_sample_tables.h lobeTable): entry j holds the
// lobe's normalised weight per steradian at θ = (π/2)·(j / (size − 1))², θ the angle between the
// texel's direction and the light's; squared spacing resolves the narrow lobes of low roughness.
#define CANDELA_IBL_LOBE_TABLE_SIZE 1024u

// ---- Push constants of the precompute passes ----

// ibl_cubemap.comp: equirectangular → cube mip 0.
struct IblCubemapPush {
    uint faceSize;
    uint supersample;  // k: k×k bilinear taps per cube texel (k ≥ 1), for sources finer than the cube
    float cubeScale;   // the float cube holds radiance × cubeScale (a power of two; < 1 keeps a half-float cube in range)
    float equirectInverseScale;  // the equirect holds radiance / equirectInverseScale (half floats kept in range)
    // The float cube's source texels are clamped to this luminance, in the equirect's stored units
    // (iblClampLuminance; their excess is the bright-texel list, engine/ibl_maps/bright_texels.h).
    // The specular cube's mip 0 is not clamped. Infinity: nothing clamped.
    float clampLuminance;
    uint pad0, pad1, pad2;
};

// ibl_cube_downsample.comp: 2×2 box filter from one mip to the next.
struct IblDownsamplePush {
    uint dstFaceSize;
    uint pad0, pad1, pad2;
};

// ibl_filter_cube.comp (the prefilter: one dispatch per mip; the irradiance cube): sample table entries
// [firstSample, firstSample + sampleCount) of engine/passes/ibl/ibl_sample_tables.h.
struct IblFilterPush {
    uint faceSize;        // of the mip written
    uint firstSample;
    uint sampleCount;
    float inverseWeight;  // 1 / the table's total weight
    uint firstLobe;       // this mip's lobe table in LobeTable (CANDELA_IBL_LOBE_TABLE_SIZE entries)
    uint pad0, pad1, pad2;
};

// ibl_irradiance_sh.comp: projection of one source mip onto SH9.
struct IblShPush {
    uint faceSize;  // of the source mip read
    float lod;      // that mip's level
    float inverseScale;  // 1 / IblCubemapPush::cubeScale: back to radiance
    uint pad1;
};

// ibl_brdf_lut.comp
struct IblLutPush {
    uint size;
    uint samples;
    uint pad0, pad1;
};

// Runtime lookup parameters, shared by the forward and skybox passes (push constants).
struct IblParams {
    /*Ignore*/ vec4 rotation;        // x = cos θ, y = sin θ of the environment rotation about +Y; zw unused
    /*Range(0, 4)*/ float intensity;  // scales the environment's radiance
    /*Ignore*/ float maxLod;         // specular levels − 1
    /*Range(0, 8)*/ float skyboxLod;  // specular mip shown by the skybox (blur)
    /*Ignore*/ float lutSize;        // BRDF LUT texels per side
};

// skybox.frag (ibl.rotation is in the rays already)
struct SkyboxPush {
    SkyRays rays;
    IblParams ibl;
};

// ---- Directions ----

// The direction through the centre of texel coordinates `uv` ∈ [0,1]² of cube face `face`
// (Vulkan/OpenGL order +X, −X, +Y, −Y, +Z, −Z). Not normalized.
CANDELA_FN vec3 cubeFaceDirection(uint face, vec2 uv) {
    float s = uv.x * 2.0f - 1.0f;
    float t = uv.y * 2.0f - 1.0f;
    if (face == 0u) return vec3(1.0f, -t, -s);
    if (face == 1u) return vec3(-1.0f, -t, s);
    if (face == 2u) return vec3(s, 1.0f, t);
    if (face == 3u) return vec3(s, -1.0f, -t);
    if (face == 4u) return vec3(s, -t, 1.0f);
    return vec3(-s, -t, -1.0f);
}

// Solid angle of the cube-face rectangle [x0,x1]×[y0,y1] (face coordinates in [−1,1]) via the
// area element atan(xy / sqrt(x² + y² + 1)).
CANDELA_FN float cubeAreaElement(float x, float y) {
    return atan(x * y, sqrt(x * x + y * y + 1.0f));
}
CANDELA_FN float cubeTexelSolidAngle(uint x, uint y, uint faceSize) {
    float inv = 1.0f / float(faceSize);
    float x0 = 2.0f * float(x) * inv - 1.0f;
    float y0 = 2.0f * float(y) * inv - 1.0f;
    float x1 = x0 + 2.0f * inv;
    float y1 = y0 + 2.0f * inv;
    return cubeAreaElement(x0, y0) - cubeAreaElement(x0, y1) - cubeAreaElement(x1, y0) + cubeAreaElement(x1, y1);
}

// World direction → the environment's own frame (see shared/environment.h: direction d samples
// what R·d sampled at rotation 0; R turns by θ about +Y).
CANDELA_FN vec3 iblLookupDirection(vec3 d, vec4 rotation) {
    return vec3(d.x * rotation.x + d.z * rotation.y, d.y, -d.x * rotation.y + d.z * rotation.x);
}

// ---- Sampling ----

// Hammersley point i of n in [0,1)².
CANDELA_FN vec2 hammersley(uint i, uint n) {
    uint bits = i;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return vec2((float(i) + 0.5f) / float(n), float(bits) * 2.3283064365386963e-10f);
}

// An orthonormal basis around unit n (Duff et al. 2017, branchless, no singularity).
CANDELA_FN mat3 basisAround(vec3 n) {
    float sz = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (sz + n.z);
    float b = n.x * n.y * a;
    vec3 t = vec3(1.0f + sz * n.x * n.x * a, sz * b, -sz * n.x);
    vec3 bt = vec3(b, sz + n.y * n.y * a, -n.y);
    return mat3(t, bt, n);
}

// GGX half-vector sample in tangent space (z = normal) for α = roughness², with cos²θ_h (so that
// the caller can evaluate D without cancellation): returns (h, cos²θ).
CANDELA_FN vec4 sampleGgxHalfVector(vec2 xi, float alpha) {
    float a2 = alpha * alpha;
    float cos2 = (1.0f - xi.y) / (1.0f + (a2 - 1.0f) * xi.y);
    float sin2 = a2 * xi.y / (1.0f + (a2 - 1.0f) * xi.y);
    float cosTheta = sqrt(cos2);
    float sinTheta = sqrt(sin2);
    float phi = 2.0f * CANDELA_PI * xi.x;
    return vec4(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta, cos2);
}

// GGX visible-normal sample (Heitz 2018, "Sampling the GGX Distribution of Visible Normals") in
// tangent space for view direction `v` (z ≥ 0) and α = roughness². With this density the estimator
// of f·cos/pdf for the specular BRDF is F · G2/G1(v), bounded by 1: low variance even at grazing views.
CANDELA_FN vec3 sampleGgxVisibleNormal(vec3 v, float alpha, vec2 xi) {
    vec3 vh = normalize(vec3(alpha * v.x, alpha * v.y, v.z));
    float lengthSquared = vh.x * vh.x + vh.y * vh.y;
    vec3 t1 = lengthSquared > 0.0f ? vec3(-vh.y, vh.x, 0.0f) * (1.0f / sqrt(lengthSquared)) : vec3(1.0f, 0.0f, 0.0f);
    vec3 t2 = cross(vh, t1);
    float r = sqrt(xi.x);
    float phi = 2.0f * CANDELA_PI * xi.y;
    float p1 = r * cos(phi);
    float s = 0.5f * (1.0f + vh.z);
    float p2 = (1.0f - s) * sqrt(max(1.0f - p1 * p1, 0.0f)) + s * r * sin(phi);
    vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(1.0f - p1 * p1 - p2 * p2, 0.0f)) * vh;
    return normalize(vec3(alpha * nh.x, alpha * nh.y, max(nh.z, 1e-6f)));
}

// Smith G1 for GGX: 2 n·x / (n·x + sqrt(α² + (1 − α²)(n·x)²)).
CANDELA_FN float smithG1(float NoX, float alpha) {
    float a2 = alpha * alpha;
    return 2.0f * NoX / (NoX + sqrt(a2 + (1.0f - a2) * NoX * NoX));
}

// GGX D from cos²θ_h and sin²θ_h without cancellation.
CANDELA_FN float ggxD(float cos2, float sin2, float alpha) {
    float a2 = alpha * alpha;
    float d = cos2 * a2 + sin2;
    return a2 / (CANDELA_PI * d * d);
}

// Cosine-weighted hemisphere sample in tangent space.
CANDELA_FN vec3 sampleCosine(vec2 xi) {
    float r = sqrt(xi.y);
    float phi = 2.0f * CANDELA_PI * xi.x;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0f - xi.y, 0.0f)));
}

// Source mip for a sample of probability density `pdf` (per steradian) among `samples`, by filtered
// importance sampling (Křivánek & Colbert 2008): the mip whose texel covers the sample's share of
// the sphere, plus `bias` (they use +1: a footprint of 4× the sample's share, less noise, more blur).
CANDELA_FN float filteredLod(float pdf, uint samples, float texelSolidAngle, float maxLod, float bias) {
    float sampleSolidAngle = 1.0f / (float(samples) * max(pdf, 1e-8f));
    return clamp(0.5f * log2(sampleSolidAngle / texelSolidAngle) + bias, 0.0f, maxLod);
}

// ---- Spherical harmonics (real, order 2; basis order Y00, Y1−1, Y10, Y11, Y2−2, Y2−1, Y20, Y21, Y22) ----

CANDELA_FN float shBasis(uint i, vec3 d) {
    if (i == 0u) return 0.282094792f;
    if (i == 1u) return 0.488602512f * d.y;
    if (i == 2u) return 0.488602512f * d.z;
    if (i == 3u) return 0.488602512f * d.x;
    if (i == 4u) return 1.092548431f * d.x * d.y;
    if (i == 5u) return 1.092548431f * d.y * d.z;
    if (i == 6u) return 0.315391565f * (3.0f * d.z * d.z - 1.0f);
    if (i == 7u) return 1.092548431f * d.x * d.z;
    return 0.546274215f * (d.x * d.x - d.y * d.y);
}

// Clamped-cosine convolution divided by π per band (Ramamoorthi & Hanrahan 2001): Â_l / π.
CANDELA_FN float shCosineBand(uint i) {
    return i == 0u ? 1.0f : (i < 4u ? 2.0f / 3.0f : 0.25f);
}

// ---- Shading ----

// Where the LUT stores (N·V, roughness): texel centres span 0..1 inclusive.
CANDELA_FN vec2 brdfLutUv(float NoV, float roughness, float size) {
    return (vec2(NoV, roughness) * (size - 1.0f) + 0.5f) / size;
}

// Specular occlusion from ambient occlusion (Lagarde & de Rousiers 2014, as Filament does).
CANDELA_FN float specularOcclusion(float NoV, float ao, float roughness) {
    return clamp(pow(NoV + ao, exp2(-16.0f * roughness - 1.0f)) - 1.0f + ao, 0.0f, 1.0f);
}

// Split-sum image-based lighting of one surface point (radiance toward the viewer):
//   specular  prefiltered · E_ss, E_ss = f0·A + B
//   diffuse   irradiance · diffuseColor · (1 − E_ss)  (what single scattering did not reflect)
// With multiscatter (Fdez-Agüera 2019, "A Multiple-Scattering Microfacet Model for Real-Time IBL"):
// the energy lost by single scattering, E_ms = 1 − (A + B), returns as
//   F_ms·E_ms, F_ms = E_ss·F_avg / (1 − E_ms·F_avg), F_avg = f0 + (1 − f0)/21,
// lit by the irradiance, and the diffuse weight becomes (1 − E_ss − F_ms·E_ms). Under a uniform
// white environment a white surface then reflects exactly 1 (white furnace).
CANDELA_FN BrdfLobes iblShadeLobes(vec3 prefiltered, vec3 irradiance, vec2 lut, vec3 f0, vec3 diffuseColor,
                                   bool multiscatter, float diffuseOcclusion, float specularOcclusionFactor) {
    vec3 singleScatter = f0 * lut.x + lut.y;
    vec3 multiScatter = vec3(0.0f);
    if (multiscatter) {
        float lost = 1.0f - (lut.x + lut.y);
        vec3 averageFresnel = f0 + (vec3(1.0f) - f0) * (1.0f / 21.0f);
        vec3 fms = singleScatter * averageFresnel / (vec3(1.0f) - lost * averageFresnel);
        multiScatter = fms * lost;
    }
    vec3 diffuseWeight = diffuseColor * max(vec3(1.0f) - singleScatter - multiScatter, vec3(0.0f));
    BrdfLobes lobes;
    lobes.specular = prefiltered * singleScatter * specularOcclusionFactor;
    lobes.diffuse = (multiScatter + diffuseWeight) * irradiance * diffuseOcclusion;
    return lobes;
}

CANDELA_FN vec3 iblShade(vec3 prefiltered, vec3 irradiance, vec2 lut, vec3 f0, vec3 diffuseColor, bool multiscatter,
                         float diffuseOcclusion, float specularOcclusionFactor) {
    BrdfLobes lobes = iblShadeLobes(prefiltered, irradiance, lut, f0, diffuseColor, multiscatter, diffuseOcclusion,
                                    specularOcclusionFactor);
    return lobes.specular + lobes.diffuse;
}

CANDELA_NAMESPACE_END

#ifdef __cplusplus
static_assert(sizeof(candela::shading::IblFilterPush) == 32);
static_assert(sizeof(candela::shading::IblCubemapPush) == 32);
static_assert(sizeof(candela::shading::IblParams) == 32);
static_assert(sizeof(candela::shading::SkyboxPush) == 80);
#endif

#endif
