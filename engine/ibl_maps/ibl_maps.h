#pragma once
// IblMaps: the persistent maps of image-based lighting (specular cube, irradiance as SH9 or cube,
// BRDF LUT) and the precompute passes that fill them. The maps live outside the render graph and
// are imported into each frame's graph. Only when the environment or the IblQuality changed does
// addToGraph also add the precompute passes (ibl_cubemap → ibl_prefilter, ibl_irradiance_*,
// ibl_sheen_prefilter when the quality asks for the sheen cube, and ibl_brdf_lut when the LUT's own
// settings changed); on every other frame the graph holds no
// precompute pass. With a cache directory, computed maps are written there after the frame and
// later runs with the same environment content and quality load them instead.
//
//     IblMaps maps(context);
//     maps.setEnvironment(&env, quality, cacheDir);  // GPU idle; uploads, or loads from the cache
//     passes::IblHandles imported = maps.addToGraph(graph, imports);  // + precompute passes if pending
//     ... execute, wait ...
//     maps.frameCompleted(graph);  // marks them computed, writes the cache
//
// The passes that read the maps get them only through the graph (passes::IblHandles), never as
// views, so a map replaced between frames cannot be bound stale.

#include "assets/environment.h"
#include "executor/graph_executor.h"
#include "graph/render_graph.h"
#include "ibl/ibl_cache_file.h"
#include "ibl/ibl_settings.h"
#include "passes/ibl/ibl_handles.h"
#include "vk/buffer.h"
#include "vk/image.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace candela::passes {
class IblCubemapPass;
class IblPrefilterPass;
class IblIrradianceShPass;
class IblIrradianceCubePass;
class IblBrdfLutPass;
}  // namespace candela::passes

namespace candela::ibl_maps {

// FNV-1a 64 of the names and current SPIR-V of the precompute's shaders (every built-in "ibl_*"
// shader; a hot-reloaded one's replacement).
uint64_t precomputeShadersHash();
// The cache key of the maps of an environment with content hash `environmentHash` at `quality`:
// the quality's canonical text and precomputeShadersHash (maps made by other code are another key's).
ibl::IblCacheKey iblCacheKey(uint64_t environmentHash, const ibl::IblQuality& quality);

// Where the maps of the current environment came from.
enum class MapsSource : uint8_t { None, Pending, Computed, Cache };

// What a frame did with the maps (IblMaps::lastFrame); the IBL lines of --explain are made from it.
struct IblFrame {
    // How the frame had its maps: none (no environment: no precompute, no skybox, no IBL shading),
    // computed by its own precompute passes, loaded from the cache file, or kept from an earlier
    // frame (environment and quality unchanged: imported, no precompute pass declared).
    enum class Maps : uint8_t { None, Computed, FromCache, Kept };
    Maps maps = Maps::None;
    bool lutComputed = false;   // false: the BRDF LUT pass left out (its settings unchanged)
    uint32_t brightTexels = 0;  // Computed: texels the filters summed instead of sampling (0: none)
    ibl::IrradianceMode irradiance = ibl::IrradianceMode::Cube;  // the other mode's pass is left out
    bool sheen = false;  // the sheen cube made (false: left out, no material has a sheen)
    bool operator==(const IblFrame&) const = default;
};

class IblMaps {
public:
    explicit IblMaps(vk::Context& context);
    ~IblMaps();
    IblMaps(const IblMaps&) = delete;
    IblMaps& operator=(const IblMaps&) = delete;

    // Uses `environment` (null: none) with `quality` from the next frame on. When the content hash
    // and quality equal the current ones nothing happens and false is returned. Otherwise the maps
    // are (re)created as needed and either loaded from `cacheDir` (non-empty, file present and
    // valid) or marked pending for the next addToGraph; returns true (views may have changed).
    // Throws UserError for an invalid quality. Precondition: the GPU no longer uses the maps.
    // `environment` is read only during the call. `force` recomputes even when nothing changed
    // (benchmarks and reports).
    bool setEnvironment(const assets::Environment* environment, const ibl::IblQuality& quality,
                        const std::filesystem::path& cacheDir, bool force = false);

    bool hasEnvironment() const { return mSource != MapsSource::None; }
    MapsSource source() const { return mSource; }
    const ibl::IblQuality& quality() const { return mQuality; }
    uint32_t specularLevels() const { return mLevels; }
    uint64_t environmentHash() const { return mEnvironmentHash; }

    // The LUT's size (1 before the first environment).
    uint32_t lutSize() const;

    // The ground truth of `ibl-report` (RenderSettings::ibl.referenceSamples > 0) reads the
    // environment itself: an RGBA32F equirectangular copy whose alpha is 0 for the brightest texels
    // (at most kMaxReferenceTexels, each more than kBrightTexelFactor × the mean luminance), and the list of those
    // texels, which the shader sums explicitly. Uploads and waits; precondition: the GPU no longer
    // uses the previous ones. addToGraph imports them when asked to.
    void setReferenceEnvironment(const assets::Environment& environment);
    uint32_t referenceTexelCount() const { return mReferenceTexelCount; }
    static constexpr uint32_t kMaxReferenceTexels = 4096;

    // Imports the maps into `graph`, preceded by the precompute passes when they are pending; with
    // `reference`, also the ground truth's inputs (setReferenceEnvironment, if it was called).
    // Precondition: hasEnvironment(). This object must outlive the graph's execution.
    // Binds every resource it imports in `imports`, with per-mip views.
    passes::IblHandles addToGraph(graph::RenderGraph& graph, graph::ImportBindings& imports, bool reference = false);

    // After the graph given to addToGraph has executed and completed: the maps its precompute
    // passes computed are marked current (and written to the cache directory, if any); the
    // environment's upload is released. Warnings (cache write failures) go to the log.
    void frameCompleted(const graph::RenderGraph& graph);

    // Copies the current maps to the host (specular mips, irradiance, LUT), for the cache, reports
    // and tests. Waits for the GPU. Precondition: hasEnvironment() and nothing pending.
    std::vector<ibl::CachedImage> readBack();

    // What the last addToGraph did and left out (none before the first, or without an environment).
    IblFrame lastFrame() const;
    // lastFrame() in words, one line each (`--explain`), with the environment and the cache file.
    std::vector<std::string> explanation() const;
    // The name of the specular cube in a graph the maps were added to (a frame lit by them declares it).
    static constexpr const char* kSpecularName = "ibl_specular";
    // The cache file used or written for the current maps (empty without a cache directory).
    const std::filesystem::path& cacheFile() const { return mCacheFile; }

    // Placeholders' and maps' formats.
    static constexpr VkFormat kSpecularFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    // The environment's equirectangular upload, read with texelFetch (no filtering needed): half
    // floats, scaled (IblCubemapPass::halfFloatScale). The ground truth's stays RGBA32F. The float
    // cube's and the LUT's formats depend on the device (vk::DeviceChoices).
    static constexpr VkFormat kEquirectFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    static constexpr VkFormat kReferenceFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    // The sheen cube's face: 64 texels (the sheen lobe is broad), or more when the levels need it.
    static uint32_t sheenFaceSize(const ibl::IblQuality& quality);
    static constexpr uint32_t kSheenSamples = 64;  // Charlie samples per texel of sheen mip 0 (4× per coarser mip)

    // How the maps rest between frames — the final state of every graph that imports them and the
    // state anything outside a graph (readBack) must wait for: sampled by the fragment shader.
    static constexpr graph::ResourceState kRestState{VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    static constexpr graph::ResourceState kShRestState{VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                                       VK_ACCESS_2_UNIFORM_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED};

private:
    struct Target {  // a persistent map with its per-mip views
        vk::Image image;
        std::vector<vk::ImageView> mipViews;
    };
    // Imports `image` into `graph` and binds it with `mipViews`.
    static graph::TextureId import(graph::RenderGraph& graph, graph::ImportBindings& imports, const char* name,
                                   const vk::Image& image, const std::vector<vk::ImageView>& mipViews,
                                   const graph::ResourceState& initial, std::optional<graph::ResourceState> final);
    // setEnvironment with the device's limits applied to `quality`.
    bool setEnvironmentAs(const assets::Environment& env, const ibl::IblQuality& quality, const std::filesystem::path& cacheDir,
                          bool force);
    void createMaps(const ibl::IblQuality& quality);
    void createPrecomputeInputs(const assets::Environment& environment);
    void ensurePasses();
    bool loadCache();
    void writeCache();
    ibl::CachedImage readImage(const char* name, const vk::Image& image);

    vk::Context& mContext;
    // Ground truth (setReferenceEnvironment).
    vk::Image mReferenceEquirect;
    vk::Buffer mReferenceTexels;
    uint32_t mReferenceTexelCount = 0;
    // Maps.
    Target mSpecular;
    Target mIrradianceCube;
    Target mLut;
    Target mSheen;  // IblQuality::sheen only
    vk::Buffer mSh;
    // Precompute inputs, alive from setEnvironment until the frame that used them completed.
    vk::Image mEquirect;
    Target mFloatCube;
    float mFloatCubeScale = 1.0f;  // the float cube holds radiance × this (IblCubemapPass::floatCubeScale)
    float mEquirectScale = 1.0f;   // the equirect holds radiance × this (IblCubemapPass::halfFloatScale)
    vk::Buffer mBright;            // ibl_maps::BrightTexels::buffer of the equirect
    float mBrightThreshold = 0.0f; // its threshold, in the equirect's units
    uint32_t mBrightCount = 0;
    // Passes (created with the first environment).
    std::unique_ptr<passes::IblCubemapPass> mCubemapPass;
    std::unique_ptr<passes::IblPrefilterPass> mPrefilterPass;
    std::unique_ptr<passes::IblIrradianceShPass> mShPass;
    std::unique_ptr<passes::IblIrradianceCubePass> mIrradianceCubePass;
    std::unique_ptr<passes::IblBrdfLutPass> mLutPass;
    std::unique_ptr<passes::IblPrefilterPass> mSheenPass;

    ibl::IblQuality mQuality;
    uint32_t mLevels = 0;
    uint64_t mEnvironmentHash = 0;
    std::string mEnvironmentName;
    uint32_t mEquirectWidth = 0, mEquirectHeight = 0;
    MapsSource mSource = MapsSource::None;
    bool mLutPending = false;
    std::string mLutComputedFor;  // lutCanonical() of the LUT's contents
    bool mPrecomputeAdded = false;  // the last addToGraph added precompute passes
    bool mLutAdded = false;
    struct LastFrame {  // what the last addToGraph did, for explanation()
        bool precompute = false;
        bool lut = false;
        MapsSource source = MapsSource::None;
    } mLastFrame;
    std::filesystem::path mCacheDir;
    std::filesystem::path mCacheFile;
    std::string mCacheNote;  // why the cache was not used / where it was written
};

}  // namespace candela::ibl_maps
