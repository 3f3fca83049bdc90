// IblMaps: copying the maps to the host (readBack, cache writes) and back (cache loads).

#include "ibl_maps/ibl_maps.h"

#include "core/cache_files.h"
#include "core/errors.h"
#include "core/log.h"
#include "shader/builtin_shaders.h"
#include "shader/shader_library.h"
#include "vk/commands.h"
#include "vk/context.h"
#include "vk/upload.h"

#include <algorithm>
#include <cstring>
#include <span>

namespace candela::ibl_maps {

namespace {

uint32_t texelBytes(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R16G16B16A16_SFLOAT: return 8;
        case VK_FORMAT_R16G16_SFLOAT: return 4;
        case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
        default: throw InternalError("IblMaps: no texel size for this format");
    }
}

}  // namespace

uint64_t precomputeShadersHash() {
    uint64_t hash = kFnv1a64Basis;
    for (const std::string_view name : shader::builtinShaderNames()) {
        if (!name.starts_with("ibl_")) continue;
        const std::span<const uint32_t> spirv = shader::shaderSpirv(name);
        hash = fnv1a64Update(hash, name.data(), name.size());
        hash = fnv1a64Update(hash, spirv.data(), spirv.size_bytes());
    }
    return hash;
}

ibl::IblCacheKey iblCacheKey(uint64_t hash, const ibl::IblQuality& quality) {
    return {hash, quality.canonical() + " shaders=" + hex16(precomputeShadersHash())};
}


ibl::CachedImage IblMaps::readImage(const char* name, const vk::Image& image) {
    const vk::ImageDesc& desc = image.desc();
    ibl::CachedImage out{.name = name,
                    .format = static_cast<uint32_t>(desc.format),
                    .texelBytes = texelBytes(desc.format),
                    .width = desc.width,
                    .height = desc.height,
                    .layers = desc.arrayLayers,
                    .mips = desc.mipLevels};
    const size_t bytes = out.expectedBytes();
    vk::Buffer staging(mContext, {.size = bytes, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  .memory = vk::MemoryUsage::Readback, .name = "ibl_readback"});
    std::vector<VkBufferImageCopy> regions;
    VkDeviceSize offset = 0;
    for (uint32_t mip = 0; mip < desc.mipLevels; ++mip) {
        const uint32_t w = std::max(desc.width >> mip, 1u), h = std::max(desc.height >> mip, 1u);
        regions.push_back({.bufferOffset = offset,
                           .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, 0, desc.arrayLayers},
                           .imageExtent = {w, h, 1}});
        offset += VkDeviceSize(w) * h * desc.arrayLayers * out.texelBytes;
    }
    vk::OneShotCommands commands(mContext);
    VkCommandBuffer cmd = commands.begin();
    // Between frames the maps rest in kRestState: whoever wrote them (the precompute passes, a cache
    // load) made the writes visible to the fragment shader, so waiting for that stage chains to them.
    vk::imageBarrier(cmd, image.handle(), VK_IMAGE_ASPECT_COLOR_BIT, kRestState.stages, VK_ACCESS_2_NONE,
                     kRestState.layout, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(),
                           static_cast<uint32_t>(regions.size()), regions.data());
    vk::imageBarrier(cmd, image.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kRestState.stages, kRestState.access, kRestState.layout);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_HOST_READ_BIT);
    commands.submitAndWait();
    staging.invalidate();
    out.data.resize(bytes);
    std::memcpy(out.data.data(), staging.mapped(), bytes);
    return out;
}

std::vector<ibl::CachedImage> IblMaps::readBack() {
    if (mSource == MapsSource::None || mSource == MapsSource::Pending || mLutPending)
        throw InternalError("IblMaps::readBack: no computed maps");
    std::vector<ibl::CachedImage> images;
    images.push_back(readImage("specular", mSpecular.image));
    if (mIrradianceCube.image) images.push_back(readImage("irradiance_cube", mIrradianceCube.image));
    if (mSh) {
        vk::Buffer staging(mContext, {.size = mSh.size(), .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                      .memory = vk::MemoryUsage::Readback, .name = "ibl_sh_readback"});
        vk::OneShotCommands commands(mContext);
        VkCommandBuffer cmd = commands.begin();
        const VkBufferCopy region{0, 0, mSh.size()};
        vk::memoryBarrier(cmd, kShRestState.stages, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_TRANSFER_READ_BIT);
        vkCmdCopyBuffer(cmd, mSh.handle(), staging.handle(), 1, &region);
        vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        commands.submitAndWait();
        staging.invalidate();
        ibl::CachedImage sh{.name = "irradiance_sh", .format = VK_FORMAT_R32G32B32A32_SFLOAT, .texelBytes = 16,
                       .width = 9, .height = 1, .layers = 1, .mips = 1};
        sh.data.resize(static_cast<size_t>(mSh.size()));
        std::memcpy(sh.data.data(), staging.mapped(), sh.data.size());
        images.push_back(std::move(sh));
    }
    images.push_back(readImage("brdf_lut", mLut.image));
    if (mSheen.image) images.push_back(readImage("sheen", mSheen.image));
    return images;
}

void IblMaps::writeCache() {
    const ibl::IblCacheKey key = iblCacheKey(mEnvironmentHash, mQuality);
    mCacheFile = ibl::cacheFilePath(mCacheDir, key);
    try {
        ibl::writeCacheFile(mCacheFile, key, readBack());
        mCacheNote = "wrote " + mCacheFile.string();
        const size_t evicted = evictCacheFiles(mCacheDir, ".cibl", ibl::kIblCacheCapBytes, mCacheFile).size();
        if (evicted)
            mCacheNote += " (" + std::to_string(evicted) + " least recently used maps removed: the folder's cap is " +
                          formatBytes(ibl::kIblCacheCapBytes) + ")";
    } catch (const UserError& e) {
        // A cache that cannot be written costs the next run a precompute; it is not an error.
        mCacheNote = std::string("not written: ") + e.what();
        log::warn("IBL cache " + mCacheNote);
    }
}

bool IblMaps::loadCache() {
    const ibl::IblCacheKey key = iblCacheKey(mEnvironmentHash, mQuality);
    const std::filesystem::path path = ibl::cacheFilePath(mCacheDir, key);
    std::string reason;
    std::optional<std::vector<ibl::CachedImage>> images = ibl::readCacheFile(path, key, &reason);
    auto miss = [&](const std::string& why) {
        mCacheNote = "miss (" + why + ")";
        return false;
    };
    if (!images) return miss(reason);
    auto find = [&](const char* name) -> const ibl::CachedImage* {
        for (const ibl::CachedImage& image : *images)
            if (image.name == name) return &image;
        return nullptr;
    };
    auto matches = [](const ibl::CachedImage* cached, const vk::Image& image) {
        const vk::ImageDesc& d = image.desc();
        return cached && cached->format == static_cast<uint32_t>(d.format) && cached->width == d.width &&
               cached->height == d.height && cached->layers == d.arrayLayers && cached->mips == d.mipLevels;
    };
    const ibl::CachedImage* specular = find("specular");
    const ibl::CachedImage* lut = find("brdf_lut");
    const ibl::CachedImage* irradiance = mIrradianceCube.image ? find("irradiance_cube") : find("irradiance_sh");
    const ibl::CachedImage* sheen = find("sheen");
    if (!matches(specular, mSpecular.image) || !matches(lut, mLut.image) || (mSheen.image && !matches(sheen, mSheen.image)) ||
        (mIrradianceCube.image && !matches(irradiance, mIrradianceCube.image)) ||
        (mSh && (!irradiance || irradiance->data.size() != mSh.size())))
        return miss(path.string() + ": maps of unexpected shape");

    vk::Uploader upload(mContext);
    auto uploadImage = [&](const ibl::CachedImage& cached, const vk::Image& image) {
        size_t offset = 0;
        for (uint32_t mip = 0; mip < cached.mips; ++mip) {
            const size_t layerBytes = size_t(std::max(cached.width >> mip, 1u)) * std::max(cached.height >> mip, 1u) *
                                      cached.texelBytes;
            for (uint32_t layer = 0; layer < cached.layers; ++layer, offset += layerBytes)
                upload.image(image, std::span(cached.data).subspan(offset, layerBytes), mip, layer,
                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        }
    };
    uploadImage(*specular, mSpecular.image);
    uploadImage(*lut, mLut.image);
    if (mIrradianceCube.image) uploadImage(*irradiance, mIrradianceCube.image);
    else upload.buffer(mSh, irradiance->data);
    if (mSheen.image) uploadImage(*sheen, mSheen.image);
    upload.submitAndWait();
    mLutComputedFor = mQuality.lutCanonical();
    mLutPending = false;
    mCacheFile = path;
    mCacheNote = "loaded " + path.string();
    touchCacheFile(path);  // recently used: evicted last
    return true;
}

}  // namespace candela::ibl_maps
