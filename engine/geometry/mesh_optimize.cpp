#include "geometry/mesh_optimize.h"

#include "core/parallel_for.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <numeric>

namespace candela::geometry {

namespace {

// One distinct mesh: an index range and what the draws using it ask of it.
struct Mesh {
    uint32_t firstIndex = 0, indexCount = 0;
    uint32_t minVertex = UINT32_MAX, maxVertex = 0;
    bool deformed = false;      // morph targets or a skin: no levels, vertices stay in place
    bool blended = false;       // some draw blends it: its triangle order stays
    bool sharesVertices = false;  // another mesh indexes the same vertices: they stay in place
    std::vector<uint32_t> draws;
};

std::vector<Mesh> distinctMeshes(const scene::Scene& scene) {
    std::map<std::pair<uint32_t, uint32_t>, size_t> byRange;
    std::vector<Mesh> meshes;
    const auto blends = [&](uint32_t material) { return scene.materials[material].alphaMode == scene::AlphaMode::Blend; };
    for (uint32_t d = 0; d < scene.draws.size(); ++d) {
        const scene::Draw& draw = scene.draws[d];
        // Points and lines are drawn as they come: no cache order, no levels (nothing simplifies them).
        if (draw.indexCount == 0 || draw.topology != scene::Topology::Triangles) continue;
        const auto [it, added] = byRange.try_emplace({draw.firstIndex, draw.indexCount}, meshes.size());
        if (added) meshes.push_back({.firstIndex = draw.firstIndex, .indexCount = draw.indexCount});
        Mesh& mesh = meshes[it->second];
        mesh.deformed |= draw.deformation >= 0 || draw.skin >= 0;
        mesh.blended |= blends(draw.material);
        mesh.draws.push_back(d);
    }
    for (const scene::DrawVariants& variants : scene.drawVariants) {
        const scene::Draw& draw = scene.draws[variants.draw];
        if (auto it = byRange.find({draw.firstIndex, draw.indexCount}); it != byRange.end())
            for (const auto& [variant, material] : variants.materials) meshes[it->second].blended |= blends(material);
    }
    for (Mesh& mesh : meshes)
        for (uint32_t i = 0; i < mesh.indexCount; ++i) {
            const uint32_t v = scene.indices[mesh.firstIndex + i];
            mesh.minVertex = std::min(mesh.minVertex, v);
            mesh.maxVertex = std::max(mesh.maxVertex, v);
        }
    // Meshes whose vertex ranges overlap keep their vertices where they are.
    std::vector<size_t> order(meshes.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return meshes[a].minVertex < meshes[b].minVertex; });
    uint32_t reach = 0;
    size_t reachMesh = SIZE_MAX;
    for (size_t i : order) {
        if (reachMesh != SIZE_MAX && meshes[i].minVertex <= reach) meshes[i].sharesVertices = meshes[reachMesh].sharesVertices = true;
        if (reachMesh == SIZE_MAX || meshes[i].maxVertex > reach) reach = meshes[i].maxVertex, reachMesh = i;
    }
    return meshes;
}

// Reorders the vertices [base, base + count) of `scene` for fetch locality in the order `local`
// (indices relative to base) first uses them, and rewrites `local`.
void reorderVertices(scene::Scene& scene, uint32_t base, uint32_t count, std::vector<uint32_t>& local) {
    std::vector<uint32_t> remap(count);
    uint32_t next = uint32_t(meshopt_optimizeVertexFetchRemap(remap.data(), local.data(), local.size(), count));
    for (uint32_t& r : remap)
        if (r == ~0u) r = next++;  // vertices no triangle uses (e.g. of dropped zero-area triangles) go last
    std::vector<scene::Vertex> reordered(count);
    meshopt_remapVertexBuffer(reordered.data(), scene.vertices.data() + base, count, sizeof(scene::Vertex), remap.data());
    std::copy(reordered.begin(), reordered.end(), scene.vertices.begin() + base);
    meshopt_remapIndexBuffer(local.data(), local.data(), local.size(), remap.data());
}

// Whether buildLevelsOfDetail gives `mesh` a chain.
bool candidate(const scene::Scene& scene, const Mesh& mesh) { return !mesh.deformed && scene.draws[mesh.draws.front()].lod < 0; }

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void prepareGeometry(scene::Scene& scene, LevelsOfDetail lod, const LodChainSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    scene::SceneLoadReport::GeometryPreparation& report = scene.report.geometry;
    const std::vector<Mesh> meshes = distinctMeshes(scene);
    report.meshes = meshes.size();
    for (const Mesh& mesh : meshes) {
        const uint32_t base = mesh.minVertex, count = mesh.maxVertex - mesh.minVertex + 1;
        std::vector<uint32_t> local(scene.indices.begin() + mesh.firstIndex,
                                    scene.indices.begin() + mesh.firstIndex + mesh.indexCount);
        for (uint32_t& i : local) i -= base;
        if (!mesh.blended) {
            meshopt_optimizeVertexCache(local.data(), local.data(), local.size(), count);
            meshopt_optimizeOverdraw(local.data(), local.data(), local.size(), &scene.vertices[base].position.x, count,
                                     sizeof(scene::Vertex), 1.05f);
        }
        if (!mesh.deformed && !mesh.sharesVertices) reorderVertices(scene, base, count, local);
        for (uint32_t i = 0; i < mesh.indexCount; ++i) scene.indices[mesh.firstIndex + i] = local[i] + base;
        report.indexBytes += uint64_t(mesh.indexCount) * sizeof(uint32_t);
        // A mesh that comes with its chain (the built-in spheres') keeps it.
        if (const int32_t given = scene.draws[mesh.draws.front()].lod; given >= 0) {
            const scene::LodChain& chain = scene.lodChains[size_t(given)];
            for (size_t i = 1; i < chain.levels.size(); ++i) report.lodIndexBytes += chain.levels[i].indexCount * sizeof(uint32_t);
            report.simplifiedMeshes += chain.levels.size() > 1;
        }
    }
    report.milliseconds = msSince(start);
    report.lodDeferred = lod == LevelsOfDetail::Defer &&
                         std::any_of(meshes.begin(), meshes.end(), [&](const Mesh& mesh) { return candidate(scene, mesh); });
    if (lod == LevelsOfDetail::Build) buildLevelsOfDetail(scene, settings);
}

std::vector<LodCandidate> lodCandidates(const scene::Scene& scene) {
    std::vector<LodCandidate> candidates;
    for (const Mesh& mesh : distinctMeshes(scene)) {
        if (!candidate(scene, mesh)) continue;
        uint64_t drawn = 0;
        for (uint32_t d : mesh.draws) drawn += uint64_t(mesh.indexCount / 3) * std::max(scene.draws[d].instanceCount, 1u);
        candidates.push_back({.firstIndex = mesh.firstIndex, .indexCount = mesh.indexCount, .firstVertex = mesh.minVertex,
                              .vertexCount = mesh.maxVertex - mesh.minVertex + 1, .drawnTriangles = drawn});
    }
    return candidates;
}

LodWork lodCandidateWork(std::span<const LodCandidate> candidates) {
    LodWork work;
    for (const LodCandidate& mesh : candidates) {
        work.builtTriangles += mesh.indexCount / 3;
        work.drawnTriangles += mesh.drawnTriangles;
    }
    return work;
}

LodWork lodCandidateWork(const scene::Scene& scene) { return lodCandidateWork(lodCandidates(scene)); }

std::vector<std::vector<SimplifiedLevel>> simplifyCandidates(const scene::Scene& scene, std::span<const LodCandidate> candidates,
                                                             const LodChainSettings& settings, uint32_t threads) {
    // The largest first: parallelFor hands them out in order.
    std::vector<size_t> order(candidates.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return candidates[a].indexCount > candidates[b].indexCount; });
    std::vector<std::vector<SimplifiedLevel>> chains(candidates.size());
    parallelFor(order.size(), [&](size_t k) {
        const LodCandidate& mesh = candidates[order[k]];
        std::vector<uint32_t> local(scene.indices.begin() + mesh.firstIndex, scene.indices.begin() + mesh.firstIndex + mesh.indexCount);
        for (uint32_t& i : local) i -= mesh.firstVertex;
        chains[order[k]] =
            simplifyChain(std::span<const scene::Vertex>(scene.vertices.data() + mesh.firstVertex, mesh.vertexCount), local, settings);
    }, threads);
    return chains;
}

void attachLevelsOfDetail(scene::Scene& scene, std::span<const LodCandidate> candidates,
                          const std::vector<std::vector<SimplifiedLevel>>& chains, double milliseconds) {
    scene::SceneLoadReport::GeometryPreparation& report = scene.report.geometry;
    std::map<std::pair<uint32_t, uint32_t>, int32_t> chainOfRange;
    for (size_t m = 0; m < candidates.size(); ++m) {
        if (chains[m].empty()) continue;
        const LodCandidate& mesh = candidates[m];
        scene::LodChain chain;
        chain.levels.push_back({mesh.firstIndex, mesh.indexCount, 0.0f});
        for (const SimplifiedLevel& level : chains[m]) {
            chain.levels.push_back({uint32_t(scene.indices.size()), uint32_t(level.indices.size()), level.error});
            for (uint32_t i : level.indices) scene.indices.push_back(i + mesh.firstVertex);
            report.lodIndexBytes += level.indices.size() * sizeof(uint32_t);
        }
        chainOfRange[{mesh.firstIndex, mesh.indexCount}] = int32_t(scene.lodChains.size());
        scene.lodChains.push_back(std::move(chain));
        ++report.simplifiedMeshes;
    }
    for (scene::Draw& draw : scene.draws)
        if (draw.topology == scene::Topology::Triangles && draw.lod < 0)
            if (auto it = chainOfRange.find({draw.firstIndex, draw.indexCount}); it != chainOfRange.end()) draw.lod = it->second;
    report.lodDeferred = false;
    report.lodMilliseconds += milliseconds;
    report.milliseconds += milliseconds;
}

void buildLevelsOfDetail(scene::Scene& scene, const LodChainSettings& settings, uint32_t threads) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<LodCandidate> candidates = lodCandidates(scene);
    const std::vector<std::vector<SimplifiedLevel>> chains = simplifyCandidates(scene, candidates, settings, threads);
    attachLevelsOfDetail(scene, candidates, chains, msSince(start));
}

}  // namespace candela::geometry
