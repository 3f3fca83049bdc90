#pragma once
// Levels of detail for a scene whose load deferred them (geometry/mesh_optimize.h), with the
// on-disk cache (geometry/lod_cache_file.h): the chains an earlier run built are read instead of
// built; otherwise the rent-or-buy choice (geometry/lod_cost.h) counts the frames earlier runs drew
// at full detail too, a run that builds stores the chains, and one that does not adds its frames to
// the record. See docs/geometry.md#the-levels-of-detail-cache.

#include "geometry/lod_cache_file.h"
#include "geometry/lod_cost.h"
#include "geometry/mesh_optimize.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace candela::geometry {

// Canonical text of everything besides the meshes that changes their chains: `settings`, the
// chain algorithm's version (kLodChainAlgorithmVersion) and meshoptimizer's.
std::string lodCacheSettings(const LodChainSettings& settings);

// The key of the chains of `candidates` (lodCandidates(scene)): a hash of each one's vertex and
// index counts, vertex positions and indices relative to its first vertex (what simplifyChain
// reads), in order; and lodCacheSettings(settings).
LodCacheKey lodCacheKey(const scene::Scene& scene, std::span<const LodCandidate> candidates, const LodChainSettings& settings);

// Gives `scene` (report.geometry.lodDeferred) its chains when they pay, or reads them:
//  - `cacheDir` holds the chains for its candidates: attached (touched: recently used);
//  - otherwise decideLevelsOfDetail with the frames drawn before this call — the larger of
//    `framesDrawn` (this process's) and the cache's record (every run's that could write it) —
//    and `framesAhead`; built and, with a cache, stored (the folder then evicted to
//    kLodCacheCapBytes); not built: framesAhead added to the record.
// `cacheDir` empty: no cache. lodErrorPixels ≤ 0 (off): nothing read, built or recorded. A damaged
// or foreign cache file is a miss (named in the reason) and is overwritten; a cache that cannot be
// written is noted in the reason and costs nothing else. Returns whether chains were attached, and
// one line for --explain. Precondition: prepareGeometry ran with LevelsOfDetail::Defer.
LodDecision provideLevelsOfDetail(scene::Scene& scene, uint64_t framesDrawn, std::optional<uint64_t> framesAhead,
                                  float lodErrorPixels, const TriangleCosts& costs, uint32_t cores,
                                  const std::filesystem::path& cacheDir, const LodChainSettings& settings = {});

}  // namespace candela::geometry
