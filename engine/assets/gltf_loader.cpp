#include "assets/gltf_loader.h"

#include "core/errors.h"
#include "assets/gltf_animations.h"
#include "assets/gltf_draco.h"
#include "assets/gltf_meshopt.h"
#include "geometry/mesh_optimize.h"
#include "assets/gltf_file.h"
#include "assets/gltf_images.h"
#include "assets/gltf_materials.h"
#include "assets/gltf_nodes.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <new>
#include <string_view>

namespace candela::assets {
namespace gltf {

// A file with thousands of line primitives must not bury the first, informative warnings.
constexpr size_t kMaxWarnings = 64;
constexpr size_t kMaxMessageLength = 400;

namespace {

// Messages quote names and URIs from the file: keep them one line and of sane length.
std::string printable(std::string text) {
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = '?';
    if (text.size() > kMaxMessageLength) text = text.substr(0, kMaxMessageLength) + "...";
    return text;
}

}  // namespace

void LoadContext::fail(const std::string& problem) const { throw UserError(path + ": " + printable(problem)); }

namespace {

// Appends `message` unless the list has it, up to the cap; the cap's line, once, then ends the
// list. `kind`: "warnings" or "notes", for that line. Also records again a line taken out
// (LoadContext::restore): the cap's line among them is kept once, as a line of its own.
void keepOnce(std::vector<std::string>& list, const std::string& message, const char* kind) {
    if (std::find(list.begin(), list.end(), message) != list.end()) return;
    if (list.size() < kMaxWarnings) list.push_back(message);
    else if (list.size() == kMaxWarnings) list.push_back(std::string("further ") + kind + " suppressed");
}

void record(std::vector<std::string>& list, const std::string& text, const char* kind) { keepOnce(list, printable(text), kind); }

}  // namespace

void LoadContext::warn(const std::string& text) const { record(*warnings, text, "warnings"); }

LoadContext::Lines LoadContext::takeSince(size_t warningsAt, size_t notesAt) const {
    Lines out;
    const auto take = [](std::vector<std::string>* list, size_t at, std::vector<std::string>& to) {
        if (!list || at >= list->size()) return;
        to.assign(std::make_move_iterator(list->begin() + std::ptrdiff_t(at)), std::make_move_iterator(list->end()));
        list->resize(at);
    };
    take(warnings, warningsAt, out.warnings);
    take(notes, notesAt, out.notes);
    return out;
}

void LoadContext::restore(const Lines& lines) const {
    for (const std::string& line : lines.warnings) keepOnce(*warnings, line, "warnings");
    if (notes)
        for (const std::string& line : lines.notes) keepOnce(*notes, line, "notes");
}

void LoadContext::note(const std::string& text) const {
    if (notes) record(*notes, text, "notes");
}

void LoadContext::tally(Severity severity, const Fact& fact, const std::string& what, size_t amount) const {
    Count& count = tallies[fact.one];
    if (count.elements == 0) count = {severity, fact, what, 0, 0};
    ++count.elements;
    count.amount += amount;
}

void LoadContext::finish() const {
    for (const auto& [key, count] : tallies) {
        const Fact& fact = count.fact;
        const std::string text =
            !fact.many ? fact.one : std::to_string(count.amount) + " " + (count.amount == 1 ? fact.one : fact.many);
        const std::string line = (count.elements == 1 ? count.firstWhat
                                                      : std::to_string(count.elements) + " " + fact.element + "s") +
                                 ": " + text;
        if (count.severity == Severity::Warning) warn(line);
        else note(line);
    }
    tallies.clear();
}

bool fitsFloat(double value) { return std::abs(value) <= double(std::numeric_limits<float>::max()); }

float toFloat(const LoadContext& ctx, double value, const std::string& what) {
    if (!fitsFloat(value)) ctx.fail(what + " is beyond single precision");
    return float(value);
}

std::string label(const char* kind, int index, const std::string& name) {
    std::string out = std::string(kind) + " " + std::to_string(index);
    if (!name.empty()) out += " ('" + (name.size() > 64 ? name.substr(0, 64) + "..." : name) + "')";
    return out;
}

}  // namespace gltf

namespace {

constexpr std::array<std::string_view, 24> kSupportedExtensions = {
    "KHR_materials_emissive_strength", "KHR_texture_transform", "KHR_materials_unlit", "KHR_materials_ior",
    "KHR_materials_specular", "KHR_materials_clearcoat", "KHR_materials_sheen", "KHR_materials_anisotropy",
    "KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_iridescence", "KHR_materials_diffuse_transmission",
    "KHR_materials_dispersion", "KHR_materials_pbrSpecularGlossiness", "KHR_materials_variants",
    "KHR_lights_punctual", "KHR_mesh_quantization", "EXT_mesh_gpu_instancing", "KHR_draco_mesh_compression",
    "EXT_meshopt_compression", "EXT_texture_webp", "KHR_texture_basisu", "KHR_node_visibility", "KHR_animation_pointer"};

// Extensions that carry metadata only: leaving them out changes nothing drawn.
constexpr std::array<std::string_view, 2> kMetadataExtensions = {"KHR_xmp", "KHR_xmp_json_ld"};

bool supported(const std::string& extension) {
    return std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), extension) != kSupportedExtensions.end();
}

void checkAsset(const gltf::LoadContext& ctx, const tinygltf::Model& model) {
    const std::string& version = model.asset.version;
    if (version.rfind("2.", 0) != 0) ctx.fail("unsupported glTF version '" + version + "' (expected 2.x)");
    for (const std::string& extension : model.extensionsRequired)
        if (!supported(extension)) ctx.fail("requires unsupported extension " + extension);
    for (const std::string& extension : model.extensionsUsed)
        if (!supported(extension) && std::find(model.extensionsRequired.begin(), model.extensionsRequired.end(),
                                               extension) == model.extensionsRequired.end()) {
            if (std::find(kMetadataExtensions.begin(), kMetadataExtensions.end(), extension) != kMetadataExtensions.end())
                ctx.note("extension " + extension + " (metadata, nothing drawn) is not read");
            else
                ctx.warn("extension " + extension + " is not supported (ignored)");
        }
}

void loadInto(const gltf::LoadContext& ctx, std::span<const uint8_t> bytes, const std::filesystem::path& path,
              const LoadOptions& options, scene::Scene& scene) {
    gltf::ParsedFile parsed = gltf::parseGltf(ctx, bytes, path, options.maxImageDimension, options.uriReader);
    tinygltf::Model& model = parsed.model;
    checkAsset(ctx, model);
    scene.report.extensionsUsed = model.extensionsUsed;
    const auto start = std::chrono::steady_clock::now();
    scene.report.decompression.meshoptViews = gltf::decodeMeshoptBufferViews(ctx, model);  // before anything reads a view
    scene.report.decompression.dracoPrimitives = gltf::decodeDracoPrimitives(ctx, model, parsed.dracoIndices);  // or a mesh
    scene.report.decompression.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    gltf::loadSamplers(ctx, model, scene);
    gltf::ImageTable images(ctx, model, std::move(parsed.uriImages), options, scene);
    // The images decode on other threads while the materials, nodes, animations and geometry load
    // (ImageTable::decodeAll, started by loadMaterials). A decode's failure is the load's error
    // before any found after the decode began, as when the decode came first.
    try {
        gltf::loadMaterials(ctx, model, images, scene);
        gltf::noteAnimatedMaterials(model, scene);  // before loadNodes: tangent frames follow animated layers
        gltf::loadVariantNames(ctx, model, scene);
        gltf::loadNodes(ctx, model, options.sceneIndex, scene);
        gltf::loadAnimations(ctx, model, scene);
        if (options.prepareGeometry)
            geometry::prepareGeometry(scene, options.deferLevelsOfDetail ? geometry::LevelsOfDetail::Defer : geometry::LevelsOfDetail::Build);
    } catch (...) {
        images.finishDecodes();  // throws the decode's failure, if it had one
        throw;
    }
    images.finishDecodes();
}

}  // namespace

scene::Scene loadGltfFromMemory(std::span<const uint8_t> bytes, const std::filesystem::path& path,
                         const LoadOptions& options) {
    scene::Scene scene;
    scene.source = path.string();
    const gltf::LoadContext ctx{path.string(), &scene.report.warnings, &scene.report.notes};
    try {
        loadInto(ctx, bytes, path, options, scene);
    } catch (const std::bad_alloc&) {
        ctx.fail("out of memory");
    }
    ctx.finish();
    return scene;
}

scene::Scene loadGltf(const std::filesystem::path& path, const LoadOptions& options) {
    std::vector<std::string> unused;
    const gltf::LoadContext ctx{path.string(), &unused, nullptr};
    std::vector<uint8_t> bytes;
    try {
        bytes = gltf::readGltfFile(ctx, path);
    } catch (const std::bad_alloc&) {
        ctx.fail("out of memory");
    }
    return loadGltfFromMemory(bytes, path, options);
}

}  // namespace candela::assets
