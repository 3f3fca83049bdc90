// The on-disk pipeline cache (vk/pipeline_cache_file.h) across two contexts, and the files it must
// ignore; pipelines built ahead of use on worker threads (vk/pipeline_cache.h, --precompile).
// Every context here runs under validation with synchronization validation: any message fails.
//
// Mesa 22.3's lavapipe keeps no pipelines in its cache: its data is the 32-byte header alone, so
// a cache hit cannot be observed here; where the driver does keep entries (data beyond the
// header), the round trip also checks that a second run finds them (no growth).
#include "gpu_test.h"
#include "temp_dir.h"

#include "assets/builtin_scenes.h"
#include "assets/procedural_sky.h"
#include "render/renderer.h"
#include "vk/pipeline_cache.h"
#include "vk/pipeline_cache_file.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <tuple>
#include <vector>

namespace candela::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::byte> readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> chars((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::byte> out(chars.size());
    std::memcpy(out.data(), chars.data(), chars.size());
    return out;
}

void writeBytes(const fs::path& path, std::span<const std::byte> bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// The pipelines `context` creates while `renderer` uploads the scene of `settings` and builds what
// that queued ahead of the scene's first frame.
uint64_t pipelinesBuiltByUpload(const vk::Context& context, Renderer& renderer, const RenderSettings& settings) {
    const uint64_t before = context.pipelineCreation().count;
    renderer.upload(settings);
    renderer.finishPipelineBuilds();
    return context.pipelineCreation().count - before;
}

// Contexts of their own (not the fixture's): each test creates and destroys several.
class PipelineCacheTest : public ::testing::Test {
protected:
    std::unique_ptr<vk::Context> makeContext(const fs::path& folder) {
        return std::make_unique<vk::Context>(vk::ContextDesc{.validation = true, .pipelineCacheFolder = folder});
    }
    // Destroys `context` after checking that validation said nothing and nothing leaked.
    static void finish(std::unique_ptr<vk::Context>& context) {
        context->waitIdleAndCollect();
        EXPECT_EQ(context->liveObjects(), 0);
        for (const vk::ValidationMessage& m : context->validationMessages())
            if (!bestPracticesNotApplicable(m.text)) ADD_FAILURE() << "validation: " << m.text;
        context.reset();
    }
    // Builds what a frame of the grid with the sky needs (graphics and compute pipelines).
    static void renderFrame(vk::Context& context) {
        const scene::Scene grid = assets::makeSphereGrid();
        Renderer renderer(context);
        renderer.capture({.width = 32, .height = 18, .scene = &grid});
    }
    fs::path file(const vk::Context& context) const { return context.pipelineCacheFile().path(); }

    TempDir mDir{"candela_pipeline_cache"};
};

TEST_F(PipelineCacheTest, SecondContextLoadsWhatTheFirstWrote) {
    auto first = makeContext(mDir.path());
    const fs::path path = file(*first);
    EXPECT_EQ(path.parent_path(), mDir.path());
    EXPECT_EQ(path.filename().string(),
              vk::pipelineCacheFileName(vk::PipelineCacheIdentity::of(first->properties())));
    EXPECT_NE(first->pipelineCacheFile().status().find("none yet"), std::string::npos) << first->pipelineCacheFile().status();
    EXPECT_FALSE(fs::exists(path));  // written at shutdown, not before
    renderFrame(*first);
    const std::vector<std::byte> written = first->pipelineCacheFile().data();
    const bool driverKeepsEntries = written.size() > 32;
    const vk::PipelineCacheIdentity identity = vk::PipelineCacheIdentity::of(first->properties());
    finish(first);

    // The file: valid for this device, holding exactly the driver's data.
    ASSERT_TRUE(fs::exists(path));
    const std::vector<std::byte> bytes = readBytes(path);
    std::span<const std::byte> data;
    EXPECT_EQ(vk::pipelineCacheFileProblem(bytes, identity, &data), "");
    EXPECT_TRUE(std::equal(data.begin(), data.end(), written.begin(), written.end()));
    EXPECT_EQ(bytes.size(), vk::kPipelineCacheFileHeaderBytes + written.size());

    auto second = makeContext(mDir.path());
    EXPECT_EQ(second->pipelineCacheFile().status().rfind("loaded ", 0), 0u) << second->pipelineCacheFile().status();
    EXPECT_EQ(second->pipelineCacheFile().loadedBytes(), written.size());
    // Handed to the driver: its cache starts with at least what was loaded.
    EXPECT_GE(second->pipelineCacheFile().data().size(), written.size());
    renderFrame(*second);
    if (driverKeepsEntries) {  // the same pipelines again: found in the cache, nothing added
        EXPECT_EQ(second->pipelineCacheFile().data().size(), written.size());
    }
    finish(second);
    // Nothing new: the file is left as it was.
    EXPECT_EQ(readBytes(path), bytes);
}

TEST_F(PipelineCacheTest, DamagedOrForeignFilesAreIgnoredAndReplaced) {
    auto probe = makeContext(mDir.path());
    const fs::path path = file(*probe);
    const vk::PipelineCacheIdentity identity = vk::PipelineCacheIdentity::of(probe->properties());
    const std::vector<std::byte> data = probe->pipelineCacheFile().data();
    finish(probe);
    const std::vector<std::byte> valid = vk::encodePipelineCacheFile(identity, data);

    std::mt19937 random(27);
    std::vector<std::byte> noise(4096);
    for (std::byte& b : noise) b = std::byte(random() & 0xff);
    vk::PipelineCacheIdentity otherUuid = identity, otherDriver = identity;
    otherUuid.cacheUUID[0] ^= 0xff;
    otherDriver.driverVersion += 1;
    std::vector<std::byte> flipped = valid;
    flipped.back() ^= std::byte(0x01);
    // The driver's own header inside a file that is otherwise right: another UUID.
    std::vector<std::byte> foreignData = data;
    foreignData[16] ^= std::byte(0xff);
    const std::vector<std::pair<std::string, std::vector<std::byte>>> cases = {
        {"random bytes", noise},
        {"empty", {}},
        {"truncated header", std::vector<std::byte>(valid.begin(), valid.begin() + 20)},
        {"truncated data", std::vector<std::byte>(valid.begin(), valid.end() - 1)},
        {"other pipelineCacheUUID", vk::encodePipelineCacheFile(otherUuid, data)},
        {"other driver version", vk::encodePipelineCacheFile(otherDriver, data)},
        {"flipped data byte", flipped},
        {"driver header of another UUID", vk::encodePipelineCacheFile(identity, foreignData)},
    };
    for (const auto& [name, contents] : cases) {
        SCOPED_TRACE(name);
        writeBytes(path, contents);
        auto context = makeContext(mDir.path());
        EXPECT_NE(context->pipelineCacheFile().status().find("ignored"), std::string::npos) << context->pipelineCacheFile().status();
        EXPECT_EQ(context->pipelineCacheFile().loadedBytes(), 0u);
        renderFrame(*context);
        finish(context);
        std::span<const std::byte> loaded;
        EXPECT_EQ(vk::pipelineCacheFileProblem(readBytes(path), identity, &loaded), "") << "not replaced by a valid file";
    }
    // An unreadable file (a folder in its place): ignored, and not replaceable (a warning at exit).
    fs::remove(path);
    fs::create_directory(path);
    auto context = makeContext(mDir.path());
    EXPECT_NE(context->pipelineCacheFile().status().find("is a directory"), std::string::npos) << context->pipelineCacheFile().status();
    finish(context);
    EXPECT_TRUE(fs::is_directory(path));
}

TEST_F(PipelineCacheTest, NoFolderKeepsTheCacheInMemory) {
    auto context = makeContext({});
    EXPECT_TRUE(context->pipelineCacheFile().path().empty());
    EXPECT_NE(context->pipelineCache(), VK_NULL_HANDLE);
    EXPECT_EQ(context->pipelineCacheFile().status(), "off (in memory only)");
    renderFrame(*context);
    finish(context);
    EXPECT_TRUE(fs::is_empty(mDir.path()));
}

// ---- pipelines built ahead of use --------------------------------------------------------------

TEST_F(GpuTest, PreparedBuildsRunOnWorkersAndFailuresSurfaceAtUse) {
    {
        WorkerPool workers(2);
        vk::PipelineCache<int> cache;
        vk::Context* ctx = &context();
        cache.prepare(workers, 1, [ctx] { return vk::Pipeline::compute(*ctx, "pattern.comp"); }, WorkerPool::Priority::Soon);
        cache.prepare(workers, 2, [ctx] { return vk::Pipeline::compute(*ctx, "no-such-shader.comp"); }, WorkerPool::Priority::Background);
        cache.prepare(workers, 3, [ctx] { return vk::Pipeline::compute(*ctx, "pattern.comp"); }, WorkerPool::Priority::Background);
        EXPECT_EQ(cache.pending(), 3u);
        EXPECT_EQ(cache.size(), 0u);
        bool madeHere = false;
        const vk::Pipeline& one = cache.get(context(), 1, [&] {
            madeHere = true;
            return vk::Pipeline{};
        });
        EXPECT_FALSE(madeHere) << "a prepared key must take the prepared build";
        EXPECT_NE(one.handle(), VK_NULL_HANDLE);
        EXPECT_THROW(cache.get(context(), 2, [] { return vk::Pipeline{}; }), std::exception);
        // The failed key is not kept: a later use builds it again.
        EXPECT_NE(cache.get(context(), 2, [&] { return vk::Pipeline::compute(context(), "pattern.comp"); }).handle(), VK_NULL_HANDLE);
        // Key 3 is never asked for: the cache's destruction keeps nothing alive.
    }
    context().waitIdleAndCollect();
    EXPECT_EQ(context().liveObjects(), 0);
}

TEST_F(GpuTest, DebugViewsPreparedInTheBackgroundDrawLikeOnesBuiltAtFirstDraw) {
    // The same debug view, once built at its first draw and once taken from the background builds:
    // identical images (the pipelines are the same), no validation message, nothing leaked.
    const scene::Scene grid = assets::makeSphereGrid();
    RenderSettings settings{.width = 64, .height = 36, .scene = &grid};
    CapturedFrame atFirstDraw, prepared;
    {
        Renderer renderer(context());
        settings.precompile = options::Precompile::Off;
        renderer.capture(settings);
        settings.debugView = options::DebugView::Roughness;
        atFirstDraw = renderer.capture(settings);
    }
    {
        Renderer renderer(context());
        settings.precompile = options::Precompile::DebugViews;
        settings.debugView = options::DebugView::None;
        renderer.capture(settings);
        renderer.capture(settings);  // the background builds start with the second frame of the same bits
        const std::vector<std::string> explained = renderer.explain();
        const auto queued = std::find_if(explained.begin(), explained.end(),
                                         [](const std::string& l) { return l.rfind("forward pipelines:", 0) == 0; });
        ASSERT_NE(queued, explained.end());
        EXPECT_EQ(queued->find(" 0 queued"), std::string::npos) << *queued;
        renderer.finishPipelineBuilds();
        settings.debugView = options::DebugView::Roughness;
        prepared = renderer.capture(settings);
    }
    EXPECT_EQ(prepared.rgba8, atFirstDraw.rgba8);
    context().waitIdleAndCollect();
    EXPECT_EQ(context().liveObjects(), 0);
}

TEST_F(GpuTest, ANewScenesPipelinesCompileWhileItUploadsForAFrameLikeTheLast) {
    // After a frame of the grid, uploading a scene with other material keys (alpha-masked) queues
    // their forward pipelines for a frame of the same bits: they are built before its first frame,
    // which then compiles nothing and draws what a renderer that never queued ahead draws.
    const scene::Scene grid = assets::makeSphereGrid();
    scene::Scene masked = assets::makeSphereGrid();
    for (scene::Material& material : masked.materials) material.alphaMode = scene::AlphaMode::Mask;
    RenderSettings settings{.width = 48, .height = 27, .scene = &masked, .precompile = options::Precompile::Off};
    CapturedFrame reference;
    {
        Renderer renderer(context());
        reference = renderer.capture(settings);
    }
    Renderer renderer(context());
    settings.precompile = options::Precompile::Frame;
    settings.scene = &grid;
    renderer.capture(settings);
    renderer.finishPipelineBuilds();
    settings.scene = &masked;
    const uint64_t before = context().pipelineCreation().count;
    const uint64_t ahead = pipelinesBuiltByUpload(context(), renderer, settings);
    EXPECT_GT(ahead, 0u) << "the masked variants compile before the scene's first frame";
    const CapturedFrame frame = renderer.capture(settings);
    EXPECT_EQ(context().pipelineCreation().count - before, ahead) << "its first frame found every pipeline built";
    EXPECT_EQ(frame.rgba8, reference.rgba8);
}

TEST_F(GpuTest, AFirstScenesPipelinesCompileWhileItUploadsForTheFrameItsSettingsGive) {
    // Before any frame, uploading a scene queues its forward pipelines for the frame its settings
    // give (FrameBuilder::firstFrameVariant): they are built by its first frame, which then creates
    // no pipeline a renderer that never queued ahead would not; a wrong guess would show as more.
    // One sample, as on lavapipe: a GPU's default of 4 leaves the guess out (below).
    const scene::Scene grid = assets::makeSphereGrid();
    const assets::Environment sky = assets::makeProceduralSky();
    std::vector<RenderSettings> cases(3, RenderSettings{.width = 48, .height = 27, .scene = &grid, .msaa = 1});
    cases[1].environment = &sky;
    cases[2].environment = &sky;
    cases[2].iblQuality.irradiance = ibl::IrradianceMode::Cube;
    cases[2].ibl.multiscatter = false;
    cases[2].shadingOptions.specularAntiAliasing = true;
    cases[2].shading = options::ShadingModel::BlinnPhong;
    cases[2].debugView = options::DebugView::Roughness;
    for (size_t c = 0; c < cases.size(); ++c) {
        SCOPED_TRACE("case " + std::to_string(c));
        RenderSettings settings = cases[c];
        settings.precompile = options::Precompile::Off;
        uint64_t before = context().pipelineCreation().count;
        CapturedFrame reference;
        uint64_t uploadAlone = 0;  // what an upload builds without the guess: the environment's precompute
        {
            Renderer renderer(context());
            uploadAlone = pipelinesBuiltByUpload(context(), renderer, settings);
            reference = renderer.capture(settings);
        }
        const uint64_t withoutAhead = context().pipelineCreation().count - before;
        settings.precompile = options::Precompile::Frame;
        before = context().pipelineCreation().count;
        Renderer renderer(context());
        EXPECT_GT(pipelinesBuiltByUpload(context(), renderer, settings), uploadAlone)
            << "the grid's variants compile before its first frame";
        const CapturedFrame frame = renderer.capture(settings);
        EXPECT_EQ(context().pipelineCreation().count - before, withoutAhead) << "the variants built ahead were the frame's";
        EXPECT_EQ(frame.rgba8, reference.rgba8);
    }
    // With MSAA the frame plan chooses alpha to coverage: no forward variant is guessed; the
    // tonemap's one pipeline (no sky: no environment) is queued, which does not depend on it.
    RenderSettings msaa = cases[0];
    msaa.msaa = 4;
    Renderer renderer(context());
    EXPECT_EQ(pipelinesBuiltByUpload(context(), renderer, msaa), 1u);
}

TEST_F(GpuTest, AFirstFramesTonemapPipelinesCompileBeforeItsSceneIsKnown) {
    // Renderer::prepareFirstFrame, given the settings without their scene (as `candela render`
    // while the file loads), queues the tonemap's pipelines of a frame without transmissive or
    // blended draws: with the sky where nothing was drawn, the covered pixels' and the sky's (which
    // does not read the image). The frame then creates no pipeline a renderer that never prepared
    // would not. A scene with transmissive draws takes other ones: what was prepared stays unused,
    // and its frame builds its own two; one with blended draws, the sky's that reads the image.
    const scene::Scene grid = assets::makeSphereGrid();
    scene::Scene glass = assets::makeSphereGrid(2);
    glass.materials[0].transmissionFactor = 1.0f;  // one transmissive sphere
    scene::Scene blended = assets::makeSphereGrid(2);
    blended.materials[0].alphaMode = scene::AlphaMode::Blend;
    const assets::Environment sky = assets::makeProceduralSky();
    const std::vector<std::tuple<const scene::Scene*, const char*, uint64_t>> scenes = {
        {&grid, "sphere grid", 0}, {&glass, "a transmissive scene", 2}, {&blended, "a blended draw", 1}};
    for (const auto& [scene, name, extra] : scenes) {
        SCOPED_TRACE(name);
        RenderSettings settings{.width = 48, .height = 27, .scene = scene, .msaa = 1, .environment = &sky};
        settings.precompile = options::Precompile::Off;
        uint64_t before = context().pipelineCreation().count;
        CapturedFrame reference;
        {
            Renderer renderer(context());
            reference = renderer.capture(settings);
        }
        const uint64_t withoutAhead = context().pipelineCreation().count - before;
        settings.precompile = options::Precompile::Frame;
        before = context().pipelineCreation().count;
        Renderer renderer(context());
        RenderSettings early = settings;
        early.scene = nullptr;
        const uint64_t beforePrepare = context().pipelineCreation().count;
        renderer.prepareFirstFrame(early);
        renderer.finishPipelineBuilds();
        EXPECT_EQ(context().pipelineCreation().count - beforePrepare, 2u) << "the covered pixels' and the sky's";
        const CapturedFrame frame = renderer.capture(settings);
        EXPECT_EQ(context().pipelineCreation().count - before, withoutAhead + extra) << "the frame took the pipelines prepared";
        EXPECT_EQ(frame.rgba8, reference.rgba8);
    }
    // --precompile off prepares nothing.
    Renderer renderer(context());
    const uint64_t before = context().pipelineCreation().count;
    renderer.prepareFirstFrame(RenderSettings{.width = 48, .height = 27, .msaa = 1, .precompile = options::Precompile::Off, .environment = &sky});
    renderer.finishPipelineBuilds();
    EXPECT_EQ(context().pipelineCreation().count, before);
}

TEST_F(GpuTest, RendererDestroyedWhileBackgroundBuildsRunLeaksNothing) {
    const scene::Scene grid = assets::makeSphereGrid();
    {
        Renderer renderer(context());
        const RenderSettings settings{.width = 32, .height = 18, .scene = &grid, .precompile = options::Precompile::DebugViews};
        renderer.capture(settings);
        renderer.capture(settings);
    }  // most of the ~25 background builds are queued or running here
    context().waitIdleAndCollect();
    EXPECT_EQ(context().liveObjects(), 0);
}

}  // namespace
}  // namespace candela::test
