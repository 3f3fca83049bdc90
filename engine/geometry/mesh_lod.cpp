#include "geometry/mesh_lod.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela::geometry {

namespace {

// A uniform grid over the triangles of a list, answering "how far is this point from the surface".
class SurfaceGrid {
public:
    SurfaceGrid(std::span<const scene::Vertex> vertices, std::span<const uint32_t> indices) : mVertices(vertices), mIndices(indices) {
        scene::Aabb bounds;
        for (uint32_t i : indices) bounds.extend(vertices[i].position);
        mOrigin = bounds.min;
        const glm::vec3 extent = glm::max(bounds.max - bounds.min, glm::vec3(1e-12f));
        // About two cells per triangle (surfaces fill few cells of a volume), at most 128 a side.
        const float cell = std::cbrt(extent.x * extent.y * extent.z / float(std::max<size_t>(indices.size() / 3, 1) * 2));
        mCell = std::max({cell, extent.x / 128.0f, extent.y / 128.0f, extent.z / 128.0f});
        mDims = glm::clamp(glm::ivec3(glm::ceil(extent / mCell)), glm::ivec3(1), glm::ivec3(128));
        // Triangles listed in every cell their box overlaps (counting sort into one array).
        std::vector<uint32_t> counts(size_t(mDims.x) * mDims.y * mDims.z + 1, 0);
        const auto forCells = [&](size_t t, auto&& visit) {
            scene::Aabb box;
            for (int c = 0; c < 3; ++c) box.extend(vertices[indices[t + c]].position);
            const glm::ivec3 lo = cellOf(box.min), hi = cellOf(box.max);
            for (int z = lo.z; z <= hi.z; ++z)
                for (int y = lo.y; y <= hi.y; ++y)
                    for (int x = lo.x; x <= hi.x; ++x) visit(index({x, y, z}));
        };
        for (size_t t = 0; t + 2 < indices.size(); t += 3) forCells(t, [&](size_t c) { ++counts[c + 1]; });
        for (size_t c = 1; c < counts.size(); ++c) counts[c] += counts[c - 1];
        mStart = counts;
        mTriangles.resize(counts.back());
        for (size_t t = 0; t + 2 < indices.size(); t += 3) forCells(t, [&](size_t c) { mTriangles[counts[c]++] = uint32_t(t); });
    }

    // The distance from p to the nearest triangle — or, as soon as a triangle within `enough` is
    // found, that triangle's distance (callers after a maximum need no more). Cells are searched
    // in growing rings until no further ring can hold a nearer triangle.
    float distance(const glm::vec3& p, float enough = 0.0f) const {
        const glm::ivec3 centre = glm::ivec3(glm::floor((p - mOrigin) / mCell));
        const int reach = std::max({std::abs(centre.x) + mDims.x, std::abs(centre.y) + mDims.y, std::abs(centre.z) + mDims.z});
        float best = std::numeric_limits<float>::infinity();
        for (int ring = 0; ring <= reach; ++ring) {
            // A triangle in ring r lies at least (r − 1) cells away.
            if (best <= float(ring - 1) * mCell || best <= enough) break;
            const glm::ivec3 lo = glm::max(centre - ring, glm::ivec3(0)), hi = glm::min(centre + ring, mDims - 1);
            for (int z = lo.z; z <= hi.z; ++z)
                for (int y = lo.y; y <= hi.y; ++y)
                    for (int x = lo.x; x <= hi.x; ++x) {
                        const glm::ivec3 c(x, y, z);
                        const glm::ivec3 offset = glm::abs(c - centre);
                        if (std::max({offset.x, offset.y, offset.z}) != ring) continue;  // inner rings are done
                        const size_t cell = index(c);
                        for (uint32_t k = mStart[cell]; k < mStart[cell + 1] && best > enough; ++k) {
                            const uint32_t t = mTriangles[k];
                            best = std::min(best, pointTriangleDistance(p, mVertices[mIndices[t]].position,
                                                                        mVertices[mIndices[t + 1]].position,
                                                                        mVertices[mIndices[t + 2]].position));
                        }
                    }
        }
        return best;
    }

private:
    glm::ivec3 cellOf(const glm::vec3& p) const { return glm::clamp(glm::ivec3(glm::floor((p - mOrigin) / mCell)), glm::ivec3(0), mDims - 1); }
    size_t index(const glm::ivec3& c) const { return (size_t(c.z) * mDims.y + c.y) * mDims.x + c.x; }

    // The distance from p to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
    static float pointTriangleDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
        const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
        const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
        if (d1 <= 0.0f && d2 <= 0.0f) return glm::length(ap);
        const glm::vec3 bp = p - b;
        const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
        if (d3 >= 0.0f && d4 <= d3) return glm::length(bp);
        const float vc = d1 * d4 - d3 * d2;
        if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return glm::length(ap - ab * (d1 / (d1 - d3)));
        const glm::vec3 cp = p - c;
        const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
        if (d6 >= 0.0f && d5 <= d6) return glm::length(cp);
        const float vb = d5 * d2 - d1 * d6;
        if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return glm::length(ap - ac * (d2 / (d2 - d6)));
        const float va = d3 * d6 - d5 * d4;
        if (va <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f)
            return glm::length(bp - (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
        const float denominator = 1.0f / (va + vb + vc);
        return glm::length(ap - ab * (vb * denominator) - ac * (vc * denominator));
    }

    std::span<const scene::Vertex> mVertices;
    std::span<const uint32_t> mIndices;
    glm::vec3 mOrigin{0.0f};
    float mCell = 1.0f;
    glm::ivec3 mDims{1};
    std::vector<uint32_t> mStart, mTriangles;
};

// The largest distance from the vertices, edge midpoints and centres of the triangles of `from` to
// `to`'s surface.
float oneSidedDeviation(std::span<const scene::Vertex> vertices, std::span<const uint32_t> from, const SurfaceGrid& to) {
    float worst = 0.0f;
    for (size_t t = 0; t + 2 < from.size(); t += 3) {
        const glm::vec3 a = vertices[from[t]].position, b = vertices[from[t + 1]].position, c = vertices[from[t + 2]].position;
        for (const glm::vec3& p : {a, (a + b) * 0.5f, (b + c) * 0.5f, (c + a) * 0.5f, (a + b + c) / 3.0f})
            worst = std::max(worst, to.distance(p, worst));  // a point nearer than the worst so far cannot raise it
    }
    return worst;
}

// The largest distance from the vertices `points` (indices, each once) to `to`'s surface.
float vertexDeviation(std::span<const scene::Vertex> vertices, std::span<const uint32_t> points, const SurfaceGrid& to) {
    float worst = 0.0f;
    for (uint32_t i : points) worst = std::max(worst, to.distance(vertices[i].position, worst));
    return worst;
}

std::vector<uint32_t> uniqueVertices(std::span<const uint32_t> indices) {
    std::vector<uint32_t> out(indices.begin(), indices.end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace

float surfaceDeviation(std::span<const scene::Vertex> vertices, std::span<const uint32_t> fine, std::span<const uint32_t> coarse) {
    return std::max(vertexDeviation(vertices, uniqueVertices(fine), SurfaceGrid(vertices, coarse)),
                    oneSidedDeviation(vertices, coarse, SurfaceGrid(vertices, fine)));
}

std::vector<SimplifiedLevel> simplifyChain(std::span<const scene::Vertex> vertices, std::span<const uint32_t> indices,
                                           const LodChainSettings& settings) {
    std::vector<SimplifiedLevel> levels;
    if (indices.size() < 3 || vertices.empty()) return levels;
    const float* positions = &vertices[0].position.x;
    // meshopt's errors are relative to the mesh's extent; this turns them into mesh units.
    const float scale = meshopt_simplifyScale(positions, vertices.size(), sizeof(scene::Vertex));
    const size_t budget = size_t(double(indices.size()) * settings.maxExtraIndices);
    size_t spent = 0;
    size_t previous = indices.size();
    std::vector<uint32_t> out(indices.size());
    const SurfaceGrid full(vertices, indices);
    const std::vector<uint32_t> fullVertices = uniqueVertices(indices);
    while (levels.size() + 1 < settings.maxLevels && previous / 3 > settings.minTriangles) {
        const size_t target = std::max<size_t>(size_t(double(previous / 3) * settings.reduction), 1) * 3;
        float error = 0.0f;
        // From the previous level (cheaper than from the full detail: a 1.04 M-triangle model
        // prepares in a third of the time); the error is measured against the full detail below.
        const std::span<const uint32_t> source = levels.empty() ? indices : std::span<const uint32_t>(levels.back().indices);
        const size_t count = meshopt_simplify(out.data(), source.data(), source.size(), positions, vertices.size(),
                                              sizeof(scene::Vertex), target, 1.0f, meshopt_SimplifyLockBorder, &error);
        if (count == 0 || double(count) > double(previous) * settings.minimumGain || spent + count > budget) break;
        SimplifiedLevel level{std::vector<uint32_t>(out.begin(), out.begin() + std::ptrdiff_t(count)), error * scale};
        // The simplifier's error estimates the quadric distance from its input; measured against
        // the full detail, the surfaces lie up to 1.7× further apart (a UV sphere): the level keeps
        // the larger, and errors grow along the chain for the choice to be monotonic.
        level.error = std::max({level.error, vertexDeviation(vertices, fullVertices, SurfaceGrid(vertices, level.indices)),
                                oneSidedDeviation(vertices, level.indices, full)});
        if (!levels.empty()) level.error = std::max(level.error, levels.back().error);
        meshopt_optimizeVertexCache(level.indices.data(), level.indices.data(), count, vertices.size());
        levels.push_back(std::move(level));
        spent += count;
        previous = count;
    }
    return levels;
}

uint32_t selectLod(const scene::LodChain& chain, float worldScale, float pixelsPerUnit, float maxPixels) {
    if (!(maxPixels > 0.0f) || !std::isfinite(pixelsPerUnit)) return 0;
    uint32_t chosen = 0;
    for (uint32_t i = 1; i < chain.levels.size(); ++i) {
        if (chain.levels[i].error * worldScale * pixelsPerUnit > maxPixels) break;
        chosen = i;
    }
    return chosen;
}

float pixelsPerUnit(const scene::ViewSetup& view, uint32_t heightPixels, const scene::Aabb& bounds) {
    // glm's projection[1][1]: clip y per view-space unit (÷ depth for a perspective projection).
    const float halfHeight = 0.5f * float(heightPixels);
    const float yScale = std::abs(view.projection[1][1]);
    const bool perspective = view.projection[3][3] == 0.0f;
    if (!perspective) return yScale * halfHeight;
    const glm::vec3 centre = 0.5f * (bounds.min + bounds.max);
    const float radius = 0.5f * glm::length(bounds.max - bounds.min);
    const float distance = glm::length(centre - view.eye) - radius;
    if (!(distance > 0.0f)) return std::numeric_limits<float>::infinity();
    return yScale * halfHeight / distance;
}

float maxScale(const glm::mat4& world) {
    // The largest singular value of the 3×3 part is √λmax(MᵀM); Gershgorin's bound on λmax (the
    // largest absolute row sum of MᵀM) is exact for the rotation × scale of a TRS node (MᵀM is then
    // diagonal) and only ever larger under shear: the chosen level errs towards detail.
    const glm::mat3 m(world);
    const glm::mat3 a = glm::transpose(m) * m;
    float bound = 0.0f;
    for (int i = 0; i < 3; ++i) bound = std::max(bound, std::abs(a[0][i]) + std::abs(a[1][i]) + std::abs(a[2][i]));
    return std::sqrt(bound);
}

}  // namespace candela::geometry
