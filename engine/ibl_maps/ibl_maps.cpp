#include "ibl_maps/ibl_maps.h"

#include "ibl_maps/bright_texels.h"

#include "core/errors.h"
#include "core/log.h"
#include "executor/graph_executor.h"
#include "passes/ibl/ibl_brdf_lut_pass.h"
#include "passes/ibl/ibl_cubemap_pass.h"
#include "passes/ibl/ibl_irradiance_cube_pass.h"
#include "passes/ibl/ibl_irradiance_sh_pass.h"
#include "passes/ibl/ibl_prefilter_pass.h"
#include "reports/ibl_errors.h"
#include "reports/ibl_reference.h"
#include "shared/ibl.h"
#include "vk/context.h"
#include "vk/upload.h"

#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <bit>
#include <span>

namespace candela::ibl_maps {

using namespace graph;

namespace {

constexpr VkDeviceSize kShBytes = passes::IblIrradianceShPass::kBytes;
// An input uploaded by vk::Uploader, which waited and made it visible to shader reads: nothing to
// wait for, already in the layout for sampling.
constexpr ResourceState kUploadedState{VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};

TextureDesc graphDesc(const vk::ImageDesc& d) {
    return {.width = d.width, .height = d.height, .mipLevels = d.mipLevels, .arrayLayers = d.arrayLayers,
            .format = d.format, .cube = d.cube};
}

// The environment's RGB texels as RGBA (alpha 1), the layout of the RGBA32F upload.
std::vector<float> rgbaTexels(const assets::Environment& env) {
    std::vector<float> rgba(env.texelCount() * 4, 1.0f);
    for (size_t i = 0; i < env.texelCount(); ++i)
        for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = env.rgb[i * 3 + c];
    return rgba;
}

// The environment's texels as RGBA half floats times `scale` (alpha 1), its equirect halved by
// 2×2 boxes until it is at most `maxSize` texels wide and high (0: as it is); sets `width`, `height`.
std::vector<uint16_t> halfTexels(const assets::Environment& env, uint32_t maxSize, float scale, uint32_t& width,
                                 uint32_t& height) {
    std::vector<float> rgb = env.rgb;
    width = env.width;
    height = env.height;
    while (maxSize && (width > maxSize || height > maxSize) && width > 1 && height > 1) {
        const uint32_t w = width / 2, h = height / 2;
        std::vector<float> half(size_t(w) * h * 3);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) {
                    const auto at = [&](uint32_t sx, uint32_t sy) { return rgb[(size_t(sy) * width + sx) * 3 + c]; };
                    half[(size_t(y) * w + x) * 3 + c] =
                        0.25f * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1));
                }
        rgb = std::move(half);
        width = w;
        height = h;
    }
    std::vector<uint16_t> out(size_t(width) * height * 4, glm::packHalf1x16(1.0f));
    for (size_t i = 0; i < size_t(width) * height; ++i)
        for (int c = 0; c < 3; ++c)
            out[i * 4 + c] = glm::packHalf1x16(std::min(rgb[i * 3 + c] * scale, CANDELA_HALF_MAX));
    return out;
}

}  // namespace

IblMaps::IblMaps(vk::Context& context) : mContext(context) {}

IblMaps::~IblMaps() = default;

void IblMaps::setReferenceEnvironment(const assets::Environment& env) {
    const auto luminance = [&](size_t i) {
        return reports::luminance({env.rgb[i * 3], env.rgb[i * 3 + 1], env.rgb[i * 3 + 2]});
    };
    const double threshold = brightCandidateLuminance(env.width, env.height, luminance);
    std::vector<uint32_t> bright;
    for (uint32_t i = 0; i < env.texelCount(); ++i)
        if (luminance(i) > threshold) bright.push_back(i);
    std::sort(bright.begin(), bright.end(), [&](uint32_t a, uint32_t b) { return luminance(a) > luminance(b); });
    if (bright.size() > kMaxReferenceTexels) bright.resize(kMaxReferenceTexels);

    std::vector<float> rgba = rgbaTexels(env);
    std::vector<glm::vec4> texels{glm::vec4(float(bright.size()), float(env.width), float(env.height), 0)};
    for (uint32_t i : bright) {
        rgba[size_t(i) * 4 + 3] = 0.0f;
        texels.emplace_back(float(i % env.width), float(i / env.width), 0.0f, 0.0f);
        texels.emplace_back(env.rgb[size_t(i) * 3], env.rgb[size_t(i) * 3 + 1], env.rgb[size_t(i) * 3 + 2], 0.0f);
    }
    mReferenceEquirect = vk::Image(mContext, {.width = env.width, .height = env.height, .format = kReferenceFormat,
                                              .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                              .name = "ibl_reference_equirect"});
    mReferenceTexels = vk::Buffer(mContext, {.size = texels.size() * sizeof(glm::vec4),
                                             .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                             .name = "ibl_reference_texels"});
    mReferenceTexelCount = static_cast<uint32_t>(bright.size());
    vk::Uploader upload(mContext);
    upload.image(mReferenceEquirect, std::as_bytes(std::span(rgba)), 0, 0, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    upload.buffer(mReferenceTexels, std::as_bytes(std::span(texels)));
    upload.submitAndWait();
}

uint32_t IblMaps::sheenFaceSize(const ibl::IblQuality& q) {
    return std::min(q.cubeSize, std::max(64u, 1u << (q.levels() - 1)));
}

uint32_t IblMaps::lutSize() const { return mLut.image ? mLut.image.desc().width : 1; }

void IblMaps::createMaps(const ibl::IblQuality& q) {
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    auto makeCube = [&](Target& target, uint32_t size, uint32_t mips, const char* name) {
        if (target.image && target.image.desc().width == size && target.image.desc().mipLevels == mips) return;
        target.image = vk::Image(mContext, {.width = size, .height = size, .mipLevels = mips, .arrayLayers = 6,
                                            .format = kSpecularFormat, .usage = usage, .cube = true, .name = name});
        target.mipViews = target.image.createMipViews();
    };
    makeCube(mSpecular, q.cubeSize, q.levels(), "ibl_specular");
    if (q.sheen) makeCube(mSheen, sheenFaceSize(q), q.levels(), "ibl_sheen");
    else mSheen = {};
    if (q.irradiance == ibl::IrradianceMode::Cube) {
        makeCube(mIrradianceCube, q.irradianceSize, 1, "ibl_irradiance");
        mSh = {};
    } else {
        mIrradianceCube = {};
        if (!mSh)
            mSh = vk::Buffer(mContext, {.size = kShBytes,
                                        .usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                 VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                        .name = "ibl_sh"});
    }
    if (!mLut.image || mLut.image.desc().width != q.lutSize) {
        mLut.image = vk::Image(mContext, {.width = q.lutSize, .height = q.lutSize,
                                          .format = passes::IblBrdfLutPass::format(mContext), .usage = usage,
                                          .name = "ibl_brdf_lut"});
        mLutComputedFor.clear();
    }
    mLutPending = mLutComputedFor != q.lutCanonical();
}

void IblMaps::createPrecomputeInputs(const assets::Environment& env) {
    // The environment in half floats: half the memory of RGBA32F (1 GiB for 16384 × 8192), times
    // a power of two that keeps its brightest texel under the half-float maximum (exact; the
    // cubemap pass divides it out).
    float brightest = 0.0f;
    for (float v : env.rgb) brightest = std::max(brightest, v);
    mEquirectScale = passes::IblCubemapPass::halfFloatScale(brightest);
    mFloatCubeScale = passes::IblCubemapPass::floatCubeScale(mContext, brightest);
    uint32_t width = 0, height = 0;
    const std::vector<uint16_t> texels = halfTexels(env, mQuality.equirectMaxSize, mEquirectScale, width, height);
    mEquirect = vk::Image(mContext, {.width = width, .height = height, .format = kEquirectFormat,
                                     .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                     .name = "ibl_equirect"});
    const BrightTexels bright = findBrightTexels(std::span(texels), width, height, mEquirectScale, mQuality.brightTexels);
    mBrightThreshold = bright.threshold;
    mBrightCount = bright.count();
    mBright = vk::Buffer(mContext, {.size = bright.buffer.size() * sizeof(glm::vec4),
                                    .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    .name = "ibl_bright_texels"});
    vk::Uploader upload(mContext);
    upload.image(mEquirect, std::as_bytes(std::span(texels)), 0, 0, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    upload.buffer(mBright, std::as_bytes(std::span(bright.buffer)));
    upload.submitAndWait();

    const uint32_t size = mQuality.cubeSize;
    const uint32_t mips = static_cast<uint32_t>(std::bit_width(size));
    mFloatCube.image = vk::Image(mContext, {.width = size, .height = size, .mipLevels = mips, .arrayLayers = 6,
                                            .format = mContext.choices().floatCube,
                                            .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT,
                                            .cube = true, .name = "ibl_float_cube"});
    mFloatCube.mipViews = mFloatCube.image.createMipViews();
}

void IblMaps::ensurePasses() {
    if (mCubemapPass) return;
    mCubemapPass = std::make_unique<passes::IblCubemapPass>(mContext);
    mPrefilterPass = std::make_unique<passes::IblPrefilterPass>(mContext);
    mShPass = std::make_unique<passes::IblIrradianceShPass>(mContext);
    mIrradianceCubePass = std::make_unique<passes::IblIrradianceCubePass>(mContext);
    mLutPass = std::make_unique<passes::IblBrdfLutPass>(mContext);
    mSheenPass = std::make_unique<passes::IblPrefilterPass>(mContext, passes::IblPrefilterPass::Lobe::Charlie);
}

bool IblMaps::setEnvironment(const assets::Environment* env, const ibl::IblQuality& quality,
                             const std::filesystem::path& cacheDir, bool force) {
    if (!env) {
        if (mSource == MapsSource::None) return false;
        mSource = MapsSource::None;
        mSpecular = {};
        mIrradianceCube = {};
        mSheen = {};
        mSh = {};
        mEquirect = {};
        mFloatCube = {};
        mBright = {};
        mCacheFile.clear();
        mCacheNote.clear();
        return true;  // the LUT stays: it does not depend on the environment
    }
    quality.validate();
    // An environment wider or higher than the device's images may be is halved until it fits.
    ibl::IblQuality effective = quality;
    const uint32_t deviceLimit = mContext.caps().limits.maxImageDimension2D;
    if (env->width > deviceLimit || env->height > deviceLimit)
        effective.equirectMaxSize = effective.equirectMaxSize ? std::min(effective.equirectMaxSize, deviceLimit) : deviceLimit;
    return setEnvironmentAs(*env, effective, cacheDir, force);
}

bool IblMaps::setEnvironmentAs(const assets::Environment& environment, const ibl::IblQuality& quality,
                               const std::filesystem::path& cacheDir, bool force) {
    const assets::Environment* env = &environment;
    const uint64_t hash = assets::contentHash(*env);
    if (!force && mSource != MapsSource::None && hash == mEnvironmentHash && quality == mQuality &&
        cacheDir == mCacheDir)
        return false;
    mQuality = quality;
    mLevels = quality.levels();
    mEnvironmentHash = hash;
    mEnvironmentName = env->source;
    mEquirectWidth = env->width;
    mEquirectHeight = env->height;
    mCacheDir = cacheDir;
    mCacheFile.clear();
    mCacheNote.clear();
    createMaps(quality);
    if (force) mLutPending = true;
    mEquirect = {};
    mFloatCube = {};
    if (!cacheDir.empty() && loadCache()) {
        mSource = MapsSource::Cache;
        return true;
    }
    createPrecomputeInputs(*env);
    ensurePasses();
    const uint32_t floatMips = mFloatCube.image.desc().mipLevels;
    mPrefilterPass->prepare(mLevels, quality.prefilterSamples, quality.cubeSize, floatMips, quality.filteredSampling,
                            quality.lodBias);
    if (quality.sheen)
        mSheenPass->prepare(mLevels, kSheenSamples, quality.cubeSize, floatMips, quality.filteredSampling, quality.lodBias);
    if (quality.irradiance == ibl::IrradianceMode::Cube)
        mIrradianceCubePass->prepare(quality.irradianceSamples, quality.cubeSize, floatMips, quality.filteredSampling,
                            quality.lodBias);
    mSource = MapsSource::Pending;
    return true;
}

TextureId IblMaps::import(RenderGraph& graph, ImportBindings& imports, const char* name, const vk::Image& image,
                          const std::vector<vk::ImageView>& mipViews, const ResourceState& initial,
                          std::optional<ResourceState> final) {
    const TextureId texture = graph.importTexture(name, graphDesc(image.desc()), initial, final);
    std::vector<VkImageView> views;
    for (const vk::ImageView& view : mipViews) views.push_back(view.get());
    imports.bind(texture, image.handle(), image.view(), std::move(views));
    return texture;
}

passes::IblHandles IblMaps::addToGraph(RenderGraph& graph, ImportBindings& imports, bool reference) {
    if (!hasEnvironment()) throw InternalError("IblMaps::addToGraph without an environment");
    passes::IblHandles maps;
    const bool computeMaps = mSource == MapsSource::Pending;
    mPrecomputeAdded = computeMaps;
    mLutAdded = mLutPending;
    mLastFrame = {.precompute = computeMaps, .lut = mLutPending, .source = mSource};
    // Maps about to be computed have no contents to keep: they start undefined.
    const ResourceState mapsInitial = computeMaps ? ResourceState{} : kRestState;
    maps.specular = import(graph, imports, kSpecularName, mSpecular.image, mSpecular.mipViews, mapsInitial, kRestState);
    if (mIrradianceCube.image)
        maps.irradianceCube = import(graph, imports, "ibl_irradiance", mIrradianceCube.image, mIrradianceCube.mipViews,
                                     mapsInitial, kRestState);
    if (mSh) {
        maps.sh = graph.importBuffer("ibl_sh", {.size = kShBytes}, computeMaps ? ResourceState{} : kShRestState,
                                     kShRestState);
        imports.bind(maps.sh, mSh.handle());
    }
    maps.lut = import(graph, imports, "ibl_brdf_lut", mLut.image, mLut.mipViews,
                      mLutPending ? ResourceState{} : kRestState, kRestState);
    if (mSheen.image) maps.sheen = import(graph, imports, "ibl_sheen", mSheen.image, mSheen.mipViews, mapsInitial, kRestState);
    if (reference && mReferenceEquirect) {
        maps.referenceEquirect = import(graph, imports, "ibl_reference_equirect", mReferenceEquirect, {}, kUploadedState, {});
        maps.referenceTexels = graph.importBuffer("ibl_reference_texels", {.size = mReferenceTexels.size()}, ResourceState{});
        imports.bind(maps.referenceTexels, mReferenceTexels.handle());
    }
    if (computeMaps || mLutPending) ensurePasses();
    if (mLutPending) maps.lut = mLutPass->add(graph, maps.lut, mQuality.lutSamples);
    if (!computeMaps) return maps;

    // The equirect was uploaded for sampling; the float cube is written whole.
    const TextureId equirect = import(graph, imports, "ibl_equirect", mEquirect, {}, kUploadedState, {});
    const TextureId cube = import(graph, imports, "ibl_float_cube", mFloatCube.image, mFloatCube.mipViews, {}, {});
    // Uploaded and waited for, like the equirect.
    const BufferId bright = graph.importBuffer("ibl_bright_texels", {.size = mBright.size()}, ResourceState{});
    imports.bind(bright, mBright.handle());
    const passes::IblCubemapPass::Outputs resampled =
        mCubemapPass->add(graph, {.equirect = equirect, .cube = cube, .specular = maps.specular,
                                  .cubeScale = mFloatCubeScale, .equirectScale = mEquirectScale,
                                  .clampLuminance = mBrightThreshold});
    const float scale = mFloatCubeScale;
    maps.specular = mPrefilterPass->add(
        graph, {.source = resampled.cube, .specular = resampled.specular, .sourceScale = scale, .bright = bright});
    if (maps.sheen.valid())
        maps.sheen = mSheenPass->add(graph, {.source = resampled.cube, .specular = maps.sheen, .sourceScale = scale,
                                             .bright = bright});
    if (mQuality.irradiance == ibl::IrradianceMode::Sh9)
        maps.sh = mShPass->add(graph, {.source = resampled.cube,
                                       .projectedFaceSize = mQuality.shSourceSize,
                                       .coefficients = maps.sh,
                                       .sourceScale = scale,
                                       .bright = bright});
    else
        maps.irradianceCube = mIrradianceCubePass->add(graph, {.source = resampled.cube,
                                                               .irradiance = maps.irradianceCube,
                                                               .sourceScale = scale,
                                                               .bright = bright});
    return maps;
}

namespace {
bool passRan(const RenderGraph& graph, const char* name) {
    const std::optional<uint32_t> pass = graph.findPass(name);
    return pass && graph.compiled().passes[*pass].cullReason == CullReason::None;
}
}  // namespace

void IblMaps::frameCompleted(const RenderGraph& graph) {
    if (mLutAdded && passRan(graph, "ibl_brdf_lut")) {
        mLutComputedFor = mQuality.lutCanonical();
        mLutPending = false;
    }
    mLutAdded = false;
    if (!mPrecomputeAdded) return;
    mPrecomputeAdded = false;
    // E.g. a pass was disabled: compute again next frame.
    if (!passRan(graph, "ibl_prefilter") || (mSheen.image && !passRan(graph, "ibl_sheen_prefilter"))) return;
    mSource = MapsSource::Computed;
    mEquirect = {};
    mFloatCube = {};
    mBright = {};
    if (!mCacheDir.empty() && !mLutPending) writeCache();
}

IblFrame IblMaps::lastFrame() const {
    if (!hasEnvironment()) return {};
    const IblFrame::Maps maps = mLastFrame.precompute                 ? IblFrame::Maps::Computed
                                : mLastFrame.source == MapsSource::Cache ? IblFrame::Maps::FromCache
                                                                         : IblFrame::Maps::Kept;
    return {.maps = maps,
            .lutComputed = mLastFrame.lut,
            .brightTexels = maps == IblFrame::Maps::Computed ? mBrightCount : 0,
            .irradiance = mQuality.irradiance,
            .sheen = mQuality.sheen};
}

std::vector<std::string> IblMaps::explanation() const {
    const IblFrame frame = lastFrame();
    std::vector<std::string> lines;
    if (frame.maps == IblFrame::Maps::None) {
        lines.emplace_back("left out: image-based lighting (no environment): no precompute, no skybox, no IBL shading");
        return lines;
    }
    lines.push_back("ibl: environment '" + mEnvironmentName + "' (" + std::to_string(mEquirectWidth) + "x" +
                    std::to_string(mEquirectHeight) + "), " + mQuality.canonical());
    switch (frame.maps) {
        case IblFrame::Maps::Computed:
            lines.emplace_back("ibl: maps computed by this frame's precompute passes");
            lines.push_back(frame.brightTexels
                                ? "ibl: " + std::to_string(frame.brightTexels) +
                                      " bright texels summed by the filters, not sampled (--ibl-bright-texels)"
                                : "left out: bright-texel sums (no texel over " + std::to_string(int(kBrightTexelFactor)) +
                                      "x the mean luminance, or --ibl-bright-texels 0)");
            break;
        case IblFrame::Maps::FromCache:
            lines.push_back("left out: IBL precompute (maps loaded from the cache " + mCacheFile.string() + ")");
            break;
        case IblFrame::Maps::Kept:
        case IblFrame::Maps::None:
            lines.emplace_back("left out: IBL precompute (environment and quality unchanged; maps imported)");
            break;
    }
    if (!frame.lutComputed) lines.emplace_back("left out: BRDF LUT pass (LUT settings unchanged)");
    lines.emplace_back(frame.irradiance == ibl::IrradianceMode::Sh9
                           ? "left out: irradiance cube (irradiance from SH9; --irradiance cube)"
                           : "left out: SH9 projection (irradiance from the cube; --irradiance sh9)");
    lines.emplace_back(frame.sheen ? "ibl: sheen cube (Charlie-prefiltered, " + std::to_string(sheenFaceSize(mQuality)) +
                                         " texels) for the scene's KHR_materials_sheen materials"
                                   : "left out: sheen cube (no material has a sheen)");
    if (!mCacheNote.empty()) lines.push_back("ibl cache: " + mCacheNote);
    return lines;
}

}  // namespace candela::ibl_maps
