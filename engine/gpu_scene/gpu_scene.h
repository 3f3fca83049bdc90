#pragma once
// GpuScene: a scene::Scene uploaded to the device — vertex and index buffers, storage buffers of
// lights, draws and materials (shared/scene_data.h layouts), textures with generated mip chains,
// samplers, and 1×1 defaults for absent textures. A normal map's mips are filtered on the CPU and
// keep, in A, the length their averaging loses (geometry/normal_map_mips.h), for specular anti-aliasing. Geometry and textures are immutable after
// upload (re-upload on change); the light and material buffers can be rewritten (live edits).

#include "geometry/image_mips.h"
#include "scene/scene.h"
#include "shared/scene_data.h"
#include "vk/buffer.h"
#include "vk/device_caps.h"
#include "vk/image.h"
#include "vk/sampler.h"

#include <array>
#include <span>
#include <vector>

namespace candela::gpu_scene {

// A draw as the forward shaders read it: world and normal matrix, material index. Precondition:
// draw.world is not singular (hidden draws are not drawn).
shading::DrawData drawData(const scene::Draw& draw);
// The draw data of every draw in order, an instanced draw taking one entry per instance (world ·
// instance matrix) — the layout of the draw buffers; hidden draws get zeros. `first[d]` receives
// the index of draw d's first entry (what the forward pass pushes; the shader adds the instance).
// Each entry's IDs (DrawData::ids) name the glTF node (Scene::nodes' source), mesh, primitive and
// instance (Scene::instanceIndices; a scene without them: the instance's place in its draw).
std::vector<shading::DrawData> drawDataOf(const scene::Scene& scene, std::span<const scene::Draw> draws, std::vector<uint32_t>* first = nullptr);
// A light as the forward shaders read it (position and range, direction and type, colour,
// intensity — 0 for a hidden light —, cone terms).
shading::LightData lightData(const scene::Light& light);
// A material's core data (factors, alpha, every core slot's texture transform) and its layer data
// (the layers' factors and their slots' texture transforms), as the forward shaders read them.
shading::MaterialData materialData(const scene::Material& material);
shading::MaterialLayerData materialLayerData(const scene::Material& material);

// The words of one vertex's record of `deformation` in GpuScene::deformationBuffer: its
// influencesPerVertex influences (CANDELA_INFLUENCE_WORDS each: joint, weight bits), then its
// targetCount deltas (CANDELA_MORPH_DELTA_WORDS each: position, normal, tangent, uv, color).
uint32_t deformationRecordWords(const scene::Deformation& deformation);
// Appends the records of `deformation`'s vertices, in vertex order, to `words` (vertex-major, so
// the records of a run of vertices are contiguous: the skin_morph pass binds only those).
void appendDeformationRecords(const scene::Deformation& deformation, std::vector<uint32_t>& words);

// The levels of a host-written image (vk::ImageDesc::hostWritten, RGBA8) as the mip chains write
// them (geometry/image_mips.h): each level's mapped texels, row pitch and size. Precondition: the
// image is host-written and still PREINITIALIZED (vk::Image::hostTexels).
std::vector<geometry::TexelLevel> hostWrittenLevels(const vk::Image& image);

// Throws UserError (one line) when an index value of `scene` passes `caps`'s
// maxDrawIndexedIndexValue — 2^24−1 on a device without fullDrawIndexUint32 (the minimum profile),
// where drawing it would be undefined. The indices are absolute in the scene's one vertex buffer,
// so this is a scene of more than 16,777,215 vertices on such a device.
void checkIndexValues(const scene::Scene& scene, const vk::DeviceCaps& caps);

class GpuScene {
public:
    // Uploads `scene` (one batched submit) with `extraLights` appended to its lights (to nothing but
    // them without `sceneLights`), and samplers limited to `maxAnisotropy`. Precondition:
    // scene.draws reference valid ranges and materials (the loader guarantees it). `scene` must
    // outlive the GpuScene.
    GpuScene(vk::Context& context, const scene::Scene& scene, const std::vector<scene::Light>& extraLights = {},
             float maxAnisotropy = 8.0f, bool sceneLights = true);

    VkBuffer vertexBuffer() const { return mVertices.handle(); }
    VkBuffer indexBuffer() const { return mIndices.handle(); }
    VkBuffer lightBuffer() const { return mLights.handle(); }
    VkBuffer drawBuffer() const { return mDraws.handle(); }
    VkBuffer materialBuffer() const { return mMaterials.handle(); }
    // The layer parameters of every material (shading::MaterialLayerData), for the layered forward
    // program; a null handle when no material has a layer (Material::layers()).
    VkBuffer materialLayerBuffer() const { return mMaterialLayers.handle(); }
    // The skin influences and morph-target deltas of every Scene::deformations entry in one buffer
    // of 32-bit words, one record per vertex (appendDeformationRecords); a null handle when the
    // scene has no deformations. The vertex and index buffers are storage buffers too (read by
    // the skin_morph pass and the visibility path's shading).
    VkBuffer deformationBuffer() const { return mDeformation.handle(); }
    // The word of that buffer where deformation `d`'s vertex 0 record starts.
    uint64_t deformationWord(size_t d) const { return mDeformationWord[d]; }
    uint32_t lightCount() const { return mLightCount; }

    // The lights and materials as the scene defines them, and as the buffers hold them now
    // (shared/scene_data.h layouts).
    const std::vector<shading::LightData>& sceneLights() const { return mSceneLights; }
    const std::vector<shading::MaterialData>& sceneMaterials() const { return mSceneMaterials; }
    const std::vector<shading::LightData>& lights() const { return mLightData; }
    const std::vector<shading::MaterialData>& materials() const { return mMaterialData; }
    // The same for the material layers (empty when no material has a layer).
    const std::vector<shading::MaterialLayerData>& sceneMaterialLayers() const { return mSceneLayers; }
    const std::vector<shading::MaterialLayerData>& materialLayers() const { return mLayerData; }
    // Rewrites the buffers (same element counts as the scene's) and waits for the copy.
    // Precondition: no frame in flight reads them (the caller waits for the GPU).
    void rewrite(const std::vector<shading::LightData>& lights, const std::vector<shading::MaterialData>& materials,
                 const std::vector<shading::MaterialLayerData>& layers);

    // The view and sampler bound to texture slot `slot` (CANDELA_TEX_*) of material `material`:
    // the material's texture, or a 1×1 default (white, or a flat normal for a normal-map slot).
    struct Binding {
        VkImageView view;
        VkSampler sampler;
    };
    Binding texture(uint32_t material, int slot) const;
    // The same for layer texture slot `slot` (CANDELA_LAYER_TEX_*).
    Binding layerTexture(uint32_t material, int slot) const;

    const scene::Scene& scene() const { return *mScene; }
    // The sizes of the vertex and index buffers in bytes (storage-buffer range checks).
    VkDeviceSize vertexBytes() const { return mVertices.size(); }
    VkDeviceSize indexBytes() const { return mIndices.size(); }
    // Device memory of the scene's textures: every image with its mips, normal-map copies included.
    VkDeviceSize textureBytes() const;
    // Device memory of Scene::images[image] with its mips and its normal-map copy, if any.
    // Precondition: image < scene().images.size().
    VkDeviceSize imageBytes(size_t image) const { return mImageBytes[image]; }

private:
    const scene::Scene* mScene;
    vk::Buffer mVertices, mIndices, mLights, mDraws, mMaterials, mMaterialLayers, mDeformation;
    std::vector<uint64_t> mDeformationWord;
    uint32_t mLightCount = 0;
    vk::Context* mContext;
    std::vector<shading::LightData> mSceneLights, mLightData;
    std::vector<shading::MaterialData> mSceneMaterials, mMaterialData;
    std::vector<shading::MaterialLayerData> mSceneLayers, mLayerData;
    std::vector<vk::Image> mImages;       // per Scene::images entry
    std::vector<vk::Image> mExtraImages;  // normal-map copies of images also read otherwise
    std::vector<VkDeviceSize> mImageBytes;  // per Scene::images entry: imageBytes()
    std::vector<vk::Sampler> mSamplers;
    vk::Sampler mDefaultSampler;
    vk::Image mWhite, mFlatNormal;
    std::vector<std::array<Binding, CANDELA_TEX_COUNT>> mBindings;             // per material, per slot
    std::vector<std::array<Binding, CANDELA_LAYER_TEX_COUNT>> mLayerBindings;  // per material, per layer slot
};

}  // namespace candela::gpu_scene
