#include "geometry/lod_cache.h"

#include "core/cache_files.h"
#include "core/errors.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <chrono>

namespace candela::geometry {
namespace {

// The shortest text that reads back as `value`.
std::string exact(float value) {
    std::array<char, 32> text{};
    const auto end = std::to_chars(text.data(), text.data() + text.size(), value).ptr;
    return std::string(text.data(), end);
}

std::vector<LodCacheMesh> shapes(std::span<const LodCandidate> candidates) {
    std::vector<LodCacheMesh> meshes;
    for (const LodCandidate& c : candidates) meshes.push_back({c.vertexCount, c.indexCount});
    return meshes;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::string lodCacheSettings(const LodChainSettings& s) {
    return "chain=" + std::to_string(kLodChainAlgorithmVersion) + " reduction=" + exact(s.reduction) +
           " minimum-gain=" + exact(s.minimumGain) + " max-extra-indices=" + exact(s.maxExtraIndices) +
           " max-levels=" + std::to_string(s.maxLevels) + " min-triangles=" + std::to_string(s.minTriangles) +
           " meshoptimizer=" + std::to_string(MESHOPTIMIZER_VERSION);
}

LodCacheKey lodCacheKey(const scene::Scene& scene, std::span<const LodCandidate> candidates, const LodChainSettings& settings) {
    constexpr size_t kChunk = 4096;
    uint64_t hash = 0;
    std::vector<uint32_t> chunk;  // positions' bits, or indices relative to the first vertex
    chunk.reserve(3 * kChunk);
    const auto feed = [&] {
        hash = wordHash64(hash, chunk.data(), chunk.size() * sizeof(uint32_t));
        chunk.clear();
    };
    for (const LodCandidate& mesh : candidates) {
        chunk = {mesh.vertexCount, mesh.indexCount};
        feed();
        for (uint32_t v = 0; v < mesh.vertexCount; ++v) {
            const glm::vec3& p = scene.vertices[mesh.firstVertex + v].position;
            for (int c = 0; c < 3; ++c) chunk.push_back(std::bit_cast<uint32_t>(p[c]));
            if (chunk.size() >= 3 * kChunk) feed();
        }
        feed();
        for (uint32_t i = 0; i < mesh.indexCount; ++i) {
            chunk.push_back(scene.indices[mesh.firstIndex + i] - mesh.firstVertex);
            if (chunk.size() >= kChunk) feed();
        }
        feed();
    }
    return {hash, lodCacheSettings(settings)};
}

LodDecision provideLevelsOfDetail(scene::Scene& scene, uint64_t framesDrawn, std::optional<uint64_t> framesAhead,
                                  float lodErrorPixels, const TriangleCosts& costs, uint32_t cores,
                                  const std::filesystem::path& cacheDir, const LodChainSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<LodCandidate> candidates = lodCandidates(scene);
    const LodWork work = lodCandidateWork(candidates);
    const auto build = [&] {
        const std::vector<std::vector<SimplifiedLevel>> chains = simplifyCandidates(scene, candidates, settings);
        attachLevelsOfDetail(scene, candidates, chains, millisecondsSince(start));
        return chains;
    };
    if (cacheDir.empty() || work.builtTriangles == 0 || !(lodErrorPixels > 0.0f)) {
        LodDecision decision = decideLevelsOfDetail(work, framesDrawn, framesAhead, lodErrorPixels, costs, cores);
        if (decision.build) build();
        return decision;
    }

    const LodCacheKey key = lodCacheKey(scene, candidates, settings);
    const std::filesystem::path path = lodCacheFilePath(cacheDir, key);
    const std::vector<LodCacheMesh> meshes = shapes(candidates);
    std::string why;
    std::optional<LodCacheRecord> record = readLodCacheFile(path, key, meshes, &why);
    if (record && record->chains) {
        attachLevelsOfDetail(scene, candidates, *record->chains, millisecondsSince(start));
        touchCacheFile(path);  // recently used: evicted last
        return {true, "levels of detail: read from the cache (" + path.string() + ", built by an earlier run)"};
    }
    std::error_code ec;
    // A file that is there but fails to read is worth a word; a missing one is the usual first run.
    const std::string ignored = !record && std::filesystem::exists(path, ec) ? "; ignored " + why : "";
    const uint64_t earlier = record ? record->framesDrawn : 0;
    const uint64_t before = std::max(framesDrawn, earlier);
    LodDecision decision = decideLevelsOfDetail(work, before, framesAhead, lodErrorPixels, costs, cores);
    if (earlier > 0 && decision.reason.ends_with(")"))  // the figures: say where the frames before this run's come from
        decision.reason.insert(decision.reason.size() - 1, "; " + std::to_string(before) + " of the frames drawn before, as the cache records");
    decision.reason += ignored;
    LodCacheRecord written;
    if (decision.build) written.chains = build();
    else written.framesDrawn = before + framesAhead.value_or(0);
    try {
        writeLodCacheFile(path, key, written);
        if (decision.build) evictCacheFiles(cacheDir, ".clod", kLodCacheCapBytes, path);
    } catch (const UserError& e) {
        decision.reason += "; not cached: " + std::string(e.what());
    }
    return decision;
}

}  // namespace candela::geometry
