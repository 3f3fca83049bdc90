#include "gpu_scene/gpu_scene.h"

#include "core/errors.h"
#include "core/parallel_for.h"
#include "geometry/image_mips.h"
#include "geometry/normal_map_mips.h"

#include "scene/texture_transform.h"
#include "shared/scene_data.h"
#include "shared/skin_morph.h"
#include "vk/context.h"
#include "vk/upload.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <span>
#include <stdexcept>

namespace candela::gpu_scene {
namespace {

using namespace shading;

VkSamplerAddressMode addressMode(scene::Wrap wrap) {
    switch (wrap) {
        case scene::Wrap::Repeat: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
        case scene::Wrap::MirroredRepeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
        case scene::Wrap::ClampToEdge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    }
    return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

VkFilter filterOf(scene::Filter f) { return f == scene::Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR; }

template <class T>
vk::Buffer uploadedBuffer(vk::Context& context, vk::Uploader& uploader, const std::vector<T>& items, const char* name,
                          VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {
    // Zero-sized buffers are invalid: keep one (unused) element.
    const VkDeviceSize size = std::max<VkDeviceSize>(items.size() * sizeof(T), sizeof(T));
    vk::Buffer buffer(context, {.size = size, .usage = usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, .name = name});
    uploader.buffer(buffer, std::as_bytes(std::span(items)));
    return buffer;
}

vk::Image solidTexture(vk::Context& context, vk::Uploader& uploader, std::array<uint8_t, 4> rgba, VkFormat format,
                       const char* name) {
    vk::Image image(context, {.format = format,
                              .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                              .name = name});
    uploader.image(image, std::as_bytes(std::span(rgba)), 0, 0, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    return image;
}

UvTransform uvTransform(const scene::TextureRef& ref) {
    // Rows of the affine KHR_texture_transform matrix (the loader's convention, shared with tangent
    // generation), plus the texture coordinate set in r0.w.
    const glm::mat3 m = scene::textureTransformMatrix(ref.transform);
    UvTransform out;
    out.r0 = glm::vec4(m[0][0], m[1][0], m[2][0], static_cast<float>(ref.texCoord));
    out.r1 = glm::vec4(m[0][1], m[1][1], m[2][1], 0.0f);
    return out;
}

}  // namespace

MaterialData materialData(const scene::Material& m) {
    MaterialData out{};
    out.baseColorFactor = m.baseColorFactor;
    out.emissive = glm::vec4(m.emissiveFactor * m.emissiveStrength, 0.0f);
    out.metallic = m.metallicFactor;
    out.roughness = m.roughnessFactor;
    out.normalScale = m.normalScale;
    out.occlusionStrength = m.occlusionStrength;
    const float mode = m.alphaMode == scene::AlphaMode::Mask ? float(CANDELA_ALPHA_MASK)
                       : m.alphaMode == scene::AlphaMode::Blend ? float(CANDELA_ALPHA_BLEND)
                                                         : float(CANDELA_ALPHA_OPAQUE);
    out.alphaCutoff = m.alphaCutoff;
    out.alphaMode = mode;
    for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot) out.uv[slot] = uvTransform(m.texture(slot));
    return out;
}

MaterialLayerData materialLayerData(const scene::Material& m) {
    MaterialLayerData out{};
    out.specularColor = m.specularColorFactor;
    out.specular = m.specularFactor;
    out.ior = m.ior;
    out.clearcoat = m.clearcoatFactor;
    out.clearcoatRoughness = m.clearcoatRoughnessFactor;
    out.clearcoatNormalScale = m.clearcoatNormalScale;
    out.sheenColor = m.sheenColorFactor;
    out.sheenRoughness = m.sheenRoughnessFactor;
    out.anisotropy = m.anisotropyStrength;
    out.anisotropyRotation = m.anisotropyRotation;
    out.anisotropyTextured = m.anisotropy.present() ? 1.0f : 0.0f;
    out.transmission = m.transmissionFactor;
    out.thickness = m.thicknessFactor;
    out.attenuationColor = m.attenuationColor;
    out.attenuationDistance = m.attenuationDistance;
    out.iridescence = m.iridescenceFactor;
    out.iridescenceIor = m.iridescenceIor;
    out.iridescenceThicknessMinimum = m.iridescenceThicknessMinimum;
    out.iridescenceThicknessMaximum = m.iridescenceThicknessMaximum;
    out.dispersion = m.dispersion;
    out.diffuseTransmission = m.diffuseTransmissionFactor;
    out.diffuseTransmissionColor = m.diffuseTransmissionColorFactor;
    for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot) out.uv[slot] = uvTransform(m.layerTexture(slot));
    return out;
}

shading::LightData lightData(const scene::Light& l) {
    using namespace shading;
    LightData out{};
    const float type = l.type == scene::LightType::Directional ? float(CANDELA_LIGHT_DIRECTIONAL)
                       : l.type == scene::LightType::Spot    ? float(CANDELA_LIGHT_SPOT)
                                                      : float(CANDELA_LIGHT_POINT);
    out.positionRange = glm::vec4(l.position, l.range);
    out.directionType = glm::vec4(glm::normalize(l.direction), type);
    out.color = l.color;
    out.intensity = l.hidden ? 0.0f : l.intensity;  // KHR_node_visibility: a hidden light keeps its slot, dark
    const float cosOuter = std::cos(l.outerConeAngle), cosInner = std::cos(l.innerConeAngle);
    const float scale = 1.0f / std::max(cosInner - cosOuter, 1e-4f);
    out.cone = glm::vec4(scale, -cosOuter * scale, 0.0f, 0.0f);
    return out;
}

shading::DrawData drawData(const scene::Draw& draw) {
    shading::DrawData data{};
    data.world = draw.world;
    // In double: the float determinant overflows for world scales near 1e13 (the loader checks the
    // double one is non-zero).
    data.normalMatrix = glm::mat4(glm::mat3(glm::transpose(glm::inverse(glm::dmat3(draw.world)))));
    data.material = glm::uvec4(draw.material, 0, 0, 0);
    return data;
}

std::vector<shading::DrawData> drawDataOf(const scene::Scene& scene, std::span<const scene::Draw> draws, std::vector<uint32_t>* first) {
    std::vector<shading::DrawData> out;
    if (first) first->clear();
    const auto id = [](int32_t index) { return index >= 0 ? uint32_t(index) : CANDELA_NO_ID; };
    for (const scene::Draw& d : draws) {
        if (first) first->push_back(uint32_t(out.size()));
        const uint32_t node = d.node >= 0 && size_t(d.node) < scene.nodes.size() ? id(scene.nodes[size_t(d.node)].source) : CANDELA_NO_ID;
        const glm::uvec4 ids(node, id(d.mesh), id(d.primitive), CANDELA_NO_ID);
        if (d.instanceCount == 0) {
            out.push_back(d.hidden ? shading::DrawData{} : drawData(d));
            out.back().ids = ids;
            continue;
        }
        for (uint32_t i = 0; i < d.instanceCount; ++i) {
            scene::Draw instance = d;
            instance.world = d.world * scene.instances[d.firstInstance + i];
            out.push_back(d.hidden ? shading::DrawData{} : drawData(instance));
            const size_t at = d.firstInstance + i;
            out.back().ids = glm::uvec4(glm::uvec3(ids), at < scene.instanceIndices.size() ? scene.instanceIndices[at] : i);
        }
    }
    return out;
}

uint32_t deformationRecordWords(const scene::Deformation& deformation) {
    return deformation.influencesPerVertex * CANDELA_INFLUENCE_WORDS + deformation.targetCount * CANDELA_MORPH_DELTA_WORDS;
}

void appendDeformationRecords(const scene::Deformation& d, std::vector<uint32_t>& words) {
    static_assert(sizeof(scene::MorphDelta) == CANDELA_MORPH_DELTA_WORDS * sizeof(uint32_t));
    static_assert(sizeof(scene::JointInfluence) == CANDELA_INFLUENCE_WORDS * sizeof(uint32_t));
    const size_t first = words.size();
    words.resize(first + size_t(d.vertexCount) * deformationRecordWords(d));
    uint32_t* out = words.data() + first;
    for (uint32_t v = 0; v < d.vertexCount; ++v) {
        for (uint32_t i = 0; i < d.influencesPerVertex; ++i, out += CANDELA_INFLUENCE_WORDS)
            std::memcpy(out, &d.influences[size_t(v) * d.influencesPerVertex + i], sizeof(scene::JointInfluence));
        for (uint32_t t = 0; t < d.targetCount; ++t, out += CANDELA_MORPH_DELTA_WORDS)
            std::memcpy(out, &d.deltas[size_t(t) * d.vertexCount + v], sizeof(scene::MorphDelta));
    }
}

void checkIndexValues(const scene::Scene& scene, const vk::DeviceCaps& caps) {
    const uint32_t limit = caps.limits.maxDrawIndexedIndexValue;
    const auto largest = std::max_element(scene.indices.begin(), scene.indices.end());
    if (largest == scene.indices.end() || *largest <= limit) return;
    throw UserError(scene.source + ": index value " + std::to_string(*largest) + " passes this device's maxDrawIndexedIndexValue (" +
                    std::to_string(limit) + (caps.features.fullDrawIndexUint32 ? "" : "; no fullDrawIndexUint32") +
                    "): the scene has too many vertices for it");
}

std::vector<geometry::TexelLevel> hostWrittenLevels(const vk::Image& image) {
    const vk::ImageDesc& d = image.desc();
    std::vector<geometry::TexelLevel> levels;
    for (uint32_t mip = 0; mip < d.mipLevels; ++mip) {
        const vk::Image::HostTexels at = image.hostTexels(mip);
        levels.push_back({reinterpret_cast<uint8_t*>(at.data), size_t(at.rowPitch), std::max(1u, d.width >> mip), std::max(1u, d.height >> mip)});
    }
    return levels;
}

GpuScene::GpuScene(vk::Context& context, const scene::Scene& scene, const std::vector<scene::Light>& extraLights, float maxAnisotropy,
                   bool sceneLights)
    : mScene(&scene), mContext(&context) {
    checkIndexValues(scene, context.caps());
    vk::Uploader uploader(context);
    // Vertices and indices are read as storage buffers too: by the skin_morph pass and by the
    // visibility path's compute shading, which fetches the triangles itself.
    mVertices = uploadedBuffer(context, uploader, scene.vertices, "vertices",
                               VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (!scene.deformations.empty()) {
        std::vector<uint32_t> words;
        for (const scene::Deformation& d : scene.deformations) {
            mDeformationWord.push_back(words.size());
            appendDeformationRecords(d, words);
        }
        mDeformation = uploadedBuffer(context, uploader, words, "deformation_records");
    }
    mIndices = uploadedBuffer(context, uploader, scene.indices, "indices",
                              VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

    std::vector<LightData>& lights = mSceneLights;
    if (sceneLights)
        for (const scene::Light& l : scene.lights) lights.push_back(lightData(l));
    for (const scene::Light& l : extraLights) lights.push_back(lightData(l));
    mLightCount = static_cast<uint32_t>(lights.size());
    mLights = uploadedBuffer(context, uploader, lights, "lights");

    const std::vector<DrawData> draws = drawDataOf(scene, scene.draws);
    mDraws = uploadedBuffer(context, uploader, draws, "draws");

    std::vector<MaterialData>& materials = mSceneMaterials;
    for (const scene::Material& m : scene.materials) materials.push_back(materialData(m));
    mMaterials = uploadedBuffer(context, uploader, materials, "materials");
    if (std::any_of(scene.materials.begin(), scene.materials.end(), [](const scene::Material& m) { return m.layers() != 0; })) {
        for (const scene::Material& m : scene.materials) mSceneLayers.push_back(materialLayerData(m));
        mMaterialLayers = uploadedBuffer(context, uploader, mSceneLayers, "material_layers");
        mLayerData = mSceneLayers;
    }
    mLightData = mSceneLights;
    mMaterialData = mSceneMaterials;

    // Which images are normal maps (of the base or of the coat) and which are read otherwise: a
    // normal map's mips keep the length its averaging loses (geometry/normal_map_mips.h), in A — an
    // image read both ways gets a second copy for its normal-map use.
    std::vector<bool> normalUse(scene.images.size()), otherUse(scene.images.size());
    for (const scene::Material& m : scene.materials) {
        const auto mark = [&](const scene::TextureRef& ref, bool normal) {
            if (ref.present() && size_t(ref.image) < scene.images.size()) (normal ? normalUse : otherUse)[size_t(ref.image)] = true;
        };
        for (const scene::TextureSlot& slot : scene::kCoreTextureSlots) mark(m.*slot.field, slot.normalMap);
        for (const scene::TextureSlot& slot : scene::kLayerTextureSlots) mark(m.*slot.field, slot.normalMap);
    }
    // A file's own levels (KTX2) are uploaded as they are, except for normal maps, whose chain must
    // carry the lost length in A (computed from level 0); other images get their mips generated: on
    // a GPU by blits, on a CPU device by the CPU (docs/textures.md#mip-chains). Where the device
    // allows (DeviceCaps::hostWrittenTextures), every level is written straight into the texture's
    // memory, without staging copies.
    const bool cpuMips = context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const bool hostWritten = context.caps().hostWrittenTextures;
    const auto upload = [&](const scene::Image& source, bool normalMap) {
        const bool fileMips = !normalMap && !source.mips.empty();
        const uint32_t mips = fileMips ? uint32_t(source.mips.size() + 1) : geometry::mipLevelCount(source.width, source.height);
        vk::Image image(context, {.width = source.width,
                                  .height = source.height,
                                  .mipLevels = mips,
                                  .format = source.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                                  .usage = hostWritten ? VkImageUsageFlags(VK_IMAGE_USAGE_SAMPLED_BIT)
                                                       : VkImageUsageFlags(VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                                                           VK_IMAGE_USAGE_TRANSFER_SRC_BIT),
                                  .name = source.name.c_str(),
                                  .hostWritten = hostWritten});
        const VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        if (hostWritten) {
            const std::vector<geometry::TexelLevel> levels = hostWrittenLevels(image);
            const auto copyLevel = [&](const geometry::TexelLevel& to, const std::vector<uint8_t>& texels) {
                if (texels.size() != size_t(to.width) * to.height * 4)
                    throw InternalError("GpuScene: " + std::to_string(texels.size()) + " bytes are not the " + std::to_string(to.width) +
                                        " x " + std::to_string(to.height) + " texels of a level of '" + source.name + "'");
                parallelForRows(to.width, to.height, [&](uint32_t y) {
                    std::memcpy(to.row(y), texels.data() + size_t(y) * to.width * 4, size_t(to.width) * 4);
                });
            };
            if (normalMap) {
                geometry::writeNormalMapMipChain(source, levels);
            } else {
                copyLevel(levels[0], source.rgba8);
                if (fileMips)
                    for (uint32_t mip = 1; mip < mips; ++mip) copyLevel(levels[mip], source.mips[mip - 1]);
                else
                    geometry::writeBoxMipChain(source, std::span(levels).subspan(1));
            }
            uploader.hostWritten(image, layout);
        } else if (normalMap) {
            const std::vector<std::vector<uint8_t>> chain = geometry::normalMapMipChain(source);
            for (uint32_t mip = 0; mip < chain.size(); ++mip) uploader.image(image, std::as_bytes(std::span(chain[mip])), mip, 0, layout);
        } else if (fileMips) {
            uploader.image(image, std::as_bytes(std::span(source.rgba8)), 0, 0, layout);
            for (uint32_t mip = 1; mip < mips; ++mip) uploader.image(image, std::as_bytes(std::span(source.mips[mip - 1])), mip, 0, layout);
        } else if (cpuMips) {
            uploader.image(image, std::as_bytes(std::span(source.rgba8)), 0, 0, layout);
            const std::vector<std::vector<uint8_t>> chain = geometry::boxMipChain(source);
            for (uint32_t mip = 1; mip < mips; ++mip) uploader.image(image, std::as_bytes(std::span(chain[mip - 1])), mip, 0, layout);
        } else {
            uploader.image(image, std::as_bytes(std::span(source.rgba8)), 0, 0, layout, /*generateMips=*/true);
        }
        return image;
    };
    // Per image: its normal-map copy in mExtraImages, or -1 (the image serves its normal-map use itself).
    std::vector<int32_t> normalCopy(scene.images.size(), -1);
    for (size_t i = 0; i < scene.images.size(); ++i) {
        mImages.push_back(upload(scene.images[i], normalUse[i] && !otherUse[i]));
        mImageBytes.push_back(mImages.back().memoryBytes());
        if (!normalUse[i] || !otherUse[i]) continue;
        normalCopy[i] = int32_t(mExtraImages.size());
        mExtraImages.push_back(upload(scene.images[i], true));
        mImageBytes.back() += mExtraImages.back().memoryBytes();
    }
    mWhite = solidTexture(context, uploader, {255, 255, 255, 255}, VK_FORMAT_R8G8B8A8_UNORM, "default white");
    mFlatNormal = solidTexture(context, uploader, {128, 128, 255, 255}, VK_FORMAT_R8G8B8A8_UNORM, "default normal");
    uploader.submitAndWait();

    for (const scene::Sampler& s : scene.samplers)
        mSamplers.push_back(vk::createSampler(context, {.filter = filterOf(s.magFilter),
                                                        .minFilter = filterOf(s.minFilter),
                                                        .mipmapMode = s.mipFilter == scene::Filter::Nearest
                                                                          ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                                          : VK_SAMPLER_MIPMAP_MODE_LINEAR,
                                                        .addressU = addressMode(s.wrapU),
                                                        .addressV = addressMode(s.wrapV),
                                                        .maxAnisotropy = maxAnisotropy,
                                                        .maxLod = s.mipmaps ? VK_LOD_CLAMP_NONE : 0.0f}));
    mDefaultSampler = vk::createSampler(context, {.addressU = VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                                  .addressV = VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                                  .maxAnisotropy = maxAnisotropy});

    // A texture's view (its normal-map copy for a normal map) and sampler, or `fallback` (1×1) with
    // the default sampler without one.
    const auto binding = [&](const scene::TextureRef& ref, const vk::Image& fallback, bool normalMap = false) {
        const bool has = ref.present() && static_cast<size_t>(ref.image) < mImages.size();
        const bool hasSampler = ref.sampler >= 0 && static_cast<size_t>(ref.sampler) < mSamplers.size();
        const vk::Image* image = !has                                     ? &fallback
                                 : normalMap && normalCopy[size_t(ref.image)] >= 0 ? &mExtraImages[size_t(normalCopy[size_t(ref.image)])]
                                                                                   : &mImages[size_t(ref.image)];
        return Binding{image->view(), hasSampler ? mSamplers[ref.sampler].get() : mDefaultSampler.get()};
    };
    // Missing textures read white (factor × 1), missing normal maps flat.
    const auto slotBinding = [&](const scene::Material& m, const scene::TextureSlot& slot) {
        return binding(m.*slot.field, slot.normalMap ? mFlatNormal : mWhite, slot.normalMap);
    };
    for (const scene::Material& m : scene.materials) {
        auto& bindings = mBindings.emplace_back();
        for (int slot = 0; slot < CANDELA_TEX_COUNT; ++slot) bindings[slot] = slotBinding(m, scene::kCoreTextureSlots[slot]);
        auto& layerBindings = mLayerBindings.emplace_back();
        for (int slot = 0; slot < CANDELA_LAYER_TEX_COUNT; ++slot) layerBindings[slot] = slotBinding(m, scene::kLayerTextureSlots[slot]);
    }
}

void GpuScene::rewrite(const std::vector<LightData>& lights, const std::vector<MaterialData>& materials,
                       const std::vector<MaterialLayerData>& layers) {
    if (lights.size() != mSceneLights.size() || materials.size() != mSceneMaterials.size() ||
        layers.size() != mSceneLayers.size())
        throw std::invalid_argument("GpuScene::rewrite: the light, material and layer counts cannot change");
    vk::Uploader uploader(*mContext);
    if (!lights.empty()) uploader.buffer(mLights, std::as_bytes(std::span(lights)));
    if (!materials.empty()) uploader.buffer(mMaterials, std::as_bytes(std::span(materials)));
    if (!layers.empty()) uploader.buffer(mMaterialLayers, std::as_bytes(std::span(layers)));
    uploader.submitAndWait();
    mLightData = lights;
    mMaterialData = materials;
    mLayerData = layers;
}

GpuScene::Binding GpuScene::texture(uint32_t material, int slot) const { return mBindings.at(material)[slot]; }

GpuScene::Binding GpuScene::layerTexture(uint32_t material, int slot) const { return mLayerBindings.at(material)[slot]; }

VkDeviceSize GpuScene::textureBytes() const {
    VkDeviceSize bytes = 0;
    for (const vk::Image& image : mImages) bytes += image.memoryBytes();
    for (const vk::Image& image : mExtraImages) bytes += image.memoryBytes();
    return bytes;
}

}  // namespace candela::gpu_scene
