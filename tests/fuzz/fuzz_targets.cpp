#include "fuzz_targets.h"

#include "assets/environment.h"
#include "assets/exr_reader.h"
#include "assets/gltf_loader.h"
#include "assets/hdr_reader.h"
#include "assets/output_file.h"
#include "core/errors.h"
#include "geometry/lod_cache_file.h"
#include "pose/scene_pose.h"
#include "pose/skinning.h"
#include "textures/ktx2_file.h"
#include "textures/webp_image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>

namespace candela::fuzz {
namespace {

// Limits well inside libFuzzer's default 2 GiB memory limit: an input may legitimately declare
// any size up to them, and the readers must refuse anything larger before allocating it.
constexpr uint32_t kMaxImageDimension = 256;  // larger images cost decode time, not coverage
constexpr uint32_t kMaxEnvWidth = 2048, kMaxEnvHeight = 1024;

[[noreturn]] void violated(const std::string& what) {
    std::fprintf(stderr, "fuzz invariant violated: %s\n", what.c_str());
    std::abort();
}

template <typename V>
bool finite(const V& v) {
    for (int i = 0; i < V::length(); ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

bool finite(const glm::mat4& m) { return finite(m[0]) && finite(m[1]) && finite(m[2]) && finite(m[3]); }

void checkTexture(const scene::Scene& s, const scene::TextureRef& t, const std::string& what) {
    if (t.image < -1 || t.image >= int(s.images.size())) violated(what + ": image index out of range");
    if (t.sampler < -1 || t.sampler >= int(s.samplers.size())) violated(what + ": sampler index out of range");
    if (t.texCoord > 1) violated(what + ": texCoord > 1");
    if (!finite(t.transform.offset) || !finite(t.transform.scale) || !std::isfinite(t.transform.rotation))
        violated(what + ": texture transform not finite");
}

void checkScene(const scene::Scene& s) {
    for (size_t i = 0; i < s.vertices.size(); ++i) {
        const scene::Vertex& v = s.vertices[i];
        const std::string what = "vertex " + std::to_string(i) + " ";
        if (!finite(v.position)) violated(what + "position not finite");
        if (!finite(v.normal)) violated(what + "normal not finite");
        if (!finite(v.tangent)) violated(what + "tangent not finite");
        if (!finite(v.uv0) || !finite(v.uv1)) violated(what + "texture coordinates not finite");
        if (!finite(v.color)) violated(what + "colour not finite");
    }
    for (uint32_t index : s.indices)
        if (index >= s.vertices.size()) violated("index " + std::to_string(index) + " >= vertex count");
    for (const scene::Draw& d : s.draws) {
        if (uint64_t(d.firstIndex) + d.indexCount > s.indices.size()) violated("draw index range past the end");
        if (d.indexCount % 3 != 0) violated("draw index count not a multiple of 3");
        if (d.material >= s.materials.size()) violated("draw material out of range");
        if (!finite(d.world)) violated("draw transform not finite");
        if (d.node >= int32_t(s.nodes.size())) violated("draw node out of range");
        if (d.deformation >= int32_t(s.deformations.size())) violated("draw deformation out of range");
        if (uint64_t(d.firstInstance) + d.instanceCount > s.instances.size()) violated("draw instance range past the end");
        if (d.skin >= int32_t(s.skins.size()) || (d.skin >= 0 && d.deformation < 0)) violated("draw skin out of range");
    }
    for (const scene::Deformation& d : s.deformations) {
        if (uint64_t(d.firstVertex) + d.vertexCount > s.vertices.size()) violated("deformation vertex range past the end");
        if (d.deltas.size() != size_t(d.targetCount) * d.vertexCount) violated("deformation delta count");
        if (d.influences.size() != size_t(d.influencesPerVertex) * d.vertexCount) violated("deformation influence count");
    }
    for (const scene::Skin& skin : s.skins) {
        if (skin.inverseBind.size() != skin.joints.size()) violated("skin matrix count");
        for (uint32_t joint : skin.joints)
            if (joint >= s.nodes.size()) violated("skin joint out of range");
    }
    for (const animation::Animation& a : s.animations)
        for (const animation::AnimationChannel& c : a.channels) {
            if (c.sampler >= a.samplers.size() || c.node >= s.nodes.size()) violated("animation channel out of range");
            if (!animation::samplerProblem(a.samplers[c.sampler], c.property).empty()) violated("animation sampler invalid");
            if (c.property == animation::AnimatedProperty::Weights && a.samplers[c.sampler].width != s.nodes[c.node].weights.size())
                violated("weights channel width differs from its node");
        }
    for (size_t i = 0; i < s.nodes.size(); ++i) {
        if (s.nodes[i].parent >= int32_t(i)) violated("node " + std::to_string(i) + " does not come after its parent");
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(s.nodes[i].world[c][r])) violated("node " + std::to_string(i) + " world transform not finite");
    }
    for (size_t i = 0; i < s.materials.size(); ++i) {
        const scene::Material& m = s.materials[i];
        const std::string what = "material " + std::to_string(i);
        if (!finite(m.baseColorFactor) || !std::isfinite(m.metallicFactor) || !std::isfinite(m.roughnessFactor) ||
            !finite(m.emissiveFactor) || !std::isfinite(m.emissiveStrength) || !std::isfinite(m.normalScale) ||
            !std::isfinite(m.occlusionStrength) || !std::isfinite(m.alphaCutoff))
            violated(what + ": factor not finite");
        for (const scene::TextureRef* t : {&m.baseColor, &m.metallicRoughness, &m.normal, &m.occlusion, &m.emissive})
            checkTexture(s, *t, what);
    }
    for (const scene::Image& image : s.images)
        if (image.width == 0 || image.height == 0 || image.rgba8.size() != size_t(image.width) * image.height * 4)
            violated("image '" + image.name + "': pixel array does not match its size");
    for (const scene::Light& l : s.lights)
        if (!finite(l.color) || !std::isfinite(l.intensity) || !std::isfinite(l.range) || !finite(l.position) ||
            !finite(l.direction) || !std::isfinite(l.innerConeAngle) || !std::isfinite(l.outerConeAngle))
            violated("light not finite");
    for (const scene::Camera& c : s.cameras)
        if (!finite(c.world) || !std::isfinite(c.yfov) || !std::isfinite(c.znear) || !std::isfinite(c.zfar) ||
            !std::isfinite(c.aspectRatio) || !std::isfinite(c.xmag) || !std::isfinite(c.ymag))
            violated("camera not finite");
    // Hidden draws (animated nodes at scale 0) have no bounds; every visible one must.
    const bool visible = std::any_of(s.draws.begin(), s.draws.end(), [](const scene::Draw& d) { return !d.hidden; });
    if (visible && (!s.bounds.valid() || !finite(s.bounds.min) || !finite(s.bounds.max))) violated("scene bounds invalid");
}

// Plays every animation at a few times (a huge one too): visible posed draws stay finite, and so
// do the deformed vertices of the first few thousand.
void playScene(const scene::Scene& s) {
    if (s.animations.empty() && s.deformations.empty()) return;
    std::vector<uint32_t> all(s.animations.size());
    for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    pose::ScenePose pose(s, all);
    for (double t : {0.0, 0.37, 1e6}) {
        pose.evaluate(t);
        for (const scene::Draw& d : pose.draws())
            if (!d.hidden && (!finite(d.world) || !d.bounds.valid())) violated("posed draw not finite");
        size_t budget = 4096;
        static const std::vector<glm::dmat4> none;
        for (uint32_t index : pose.deformedDraws()) {
            const scene::Draw& d = pose.draws()[index];
            if (s.deformations[size_t(d.deformation)].vertexCount > budget) break;
            budget -= s.deformations[size_t(d.deformation)].vertexCount;
            for (const scene::Vertex& v : pose::deformVertices(s, d, pose.weights(d), d.skin >= 0 ? pose.jointMatrices(uint32_t(d.skin)) : none))
                if (!finite(v.position)) violated("deformed vertex not finite");
        }
    }
}

void checkEnvironment(const assets::Environment& env) {
    if (env.width == 0 || env.height == 0 || env.width > kMaxEnvWidth || env.height > kMaxEnvHeight)
        violated("environment size out of range");
    if (env.rgb.size() != env.texelCount() * 3) violated("environment texel array does not match its size");
    for (float v : env.rgb)
        if (!std::isfinite(v) || v < 0.0f) violated("environment texel not finite or negative after sanitizing");
}

void decodeEnvironment(assets::Environment (*decode)(std::span<const uint8_t>, const std::string&,
                                                    const assets::EnvironmentLoadOptions&),
                       const uint8_t* data, size_t size) {
    const assets::EnvironmentLoadOptions options{.maxWidth = kMaxEnvWidth, .maxHeight = kMaxEnvHeight};
    try {
        assets::Environment env = decode(std::span<const uint8_t>(data, size), "fuzz", options);
        assets::sanitizeEnvironment(env);
        checkEnvironment(env);
    } catch (const UserError&) {
    }
}

}  // namespace

void fuzzGltf(const uint8_t* data, size_t size, const std::filesystem::path& uriFolder) {
    try {
        const scene::Scene s = assets::loadGltfFromMemory(std::span<const uint8_t>(data, size), uriFolder / "fuzz.gltf",
                                                         assets::LoadOptions{.maxImageDimension = kMaxImageDimension});
        checkScene(s);
        playScene(s);
    } catch (const UserError&) {
    }
}

void fuzzHdr(const uint8_t* data, size_t size) { decodeEnvironment(&assets::decodeHdr, data, size); }

void fuzzExr(const uint8_t* data, size_t size) { decodeEnvironment(&assets::decodeExr, data, size); }

namespace {

// A decoded texture's levels: level 0 at most kMaxImageDimension per side, each further level the
// previous one halved (at least 1), each holding width × height × 4 bytes.
void checkLevels(const textures::DecodedTexture& texture, const char* what) {
    if (texture.levels.empty()) violated(std::string(what) + ": no level");
    for (size_t i = 0; i < texture.levels.size(); ++i) {
        const textures::TextureLevel& level = texture.levels[i];
        const std::string name = std::string(what) + " level " + std::to_string(i);
        if (level.width == 0 || level.height == 0) violated(name + ": empty");
        if (i == 0 && (level.width > kMaxImageDimension || level.height > kMaxImageDimension)) violated(name + ": above the limit");
        if (i > 0 && (level.width != std::max(1u, texture.levels[i - 1].width / 2) ||
                      level.height != std::max(1u, texture.levels[i - 1].height / 2)))
            violated(name + ": not half the previous level");
        if (level.rgba8.size() != size_t(level.width) * level.height * 4) violated(name + ": wrong byte count");
    }
}

template <typename Decode>
void decodeTexture(Decode decode, const uint8_t* data, size_t size, const char* what) {
    try {
        checkLevels(decode(std::span<const uint8_t>(data, size), kMaxImageDimension), what);
    } catch (const UserError&) {
        // Refused cleanly.
    }
}

}  // namespace

void fuzzKtx2(const uint8_t* data, size_t size) { decodeTexture(&textures::decodeKtx2, data, size, "KTX2"); }

void fuzzWebp(const uint8_t* data, size_t size) { decodeTexture(&textures::decodeWebp, data, size, "WebP"); }

void fuzzNpy(const uint8_t* data, size_t size) {
    const std::span<const uint8_t> bytes(data, size);
    if (!assets::npyComplete(bytes)) return;
    // Complete: a version 1.0 header of the length it declares, then a whole number of values.
    const size_t header = 10 + (size_t(data[8]) | size_t(data[9]) << 8);
    if (size < header || (size - header) % 4 != 0) violated("npyComplete accepted a file its header does not describe");
}

const geometry::LodCacheKey kFuzzLodCacheKey{0xf022f022f022f022ull, "fuzz"};
const std::vector<geometry::LodCacheMesh> kFuzzLodCacheMeshes = {{.vertexCount = 64, .indexCount = 96},
                                                                 {.vertexCount = 8, .indexCount = 12}};

void fuzzLodCache(const uint8_t* data, size_t size) {
    const std::optional<geometry::LodCacheRecord> record = geometry::parseLodCache(
        std::span(reinterpret_cast<const std::byte*>(data), size), kFuzzLodCacheKey, kFuzzLodCacheMeshes, nullptr);
    if (!record || !record->chains) return;
    // What attachLevelsOfDetail relies on: chains for every mesh, each level coarser than the one
    // before, whole triangles, indices within the mesh.
    if (record->chains->size() != kFuzzLodCacheMeshes.size()) violated("LOD cache: chains for another number of meshes");
    for (size_t m = 0; m < record->chains->size(); ++m) {
        size_t finer = kFuzzLodCacheMeshes[m].indexCount;
        for (const geometry::SimplifiedLevel& level : (*record->chains)[m]) {
            if (level.indices.empty() || level.indices.size() % 3 != 0 || level.indices.size() >= finer)
                violated("LOD cache: a level's index count breaks the layout");
            for (uint32_t i : level.indices)
                if (i >= kFuzzLodCacheMeshes[m].vertexCount) violated("LOD cache: an index beyond its mesh");
            finer = level.indices.size();
        }
    }
}

}  // namespace candela::fuzz
