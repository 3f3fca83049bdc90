#include "pose/skinning.h"

#include <cmath>
#include <limits>

namespace candela::pose {
namespace {

glm::dvec3 transformPoint(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

// The cofactor matrix of m's upper 3×3: transforms normals as the inverse transpose does, up to
// a positive factor (det m), with no division.
glm::dmat3 cofactor(const glm::dmat3& m) {
    return glm::dmat3(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
}

glm::dvec3 unit(const glm::dvec3& v) {
    const double length = glm::length(v);
    return length > 0.0 ? v / length : v;
}

}  // namespace

void jointMatrices(const scene::Skin& skin, const std::vector<animation::SceneNode>& nodes, std::vector<glm::dmat4>& out) {
    out.resize(skin.joints.size());
    for (size_t j = 0; j < skin.joints.size(); ++j) out[j] = nodes[skin.joints[j]].world * glm::dmat4(skin.inverseBind[j]);
}

std::vector<scene::Aabb> jointMeshBounds(const scene::Deformation& deformation, const scene::Skin& skin, std::span<const scene::Vertex> vertices) {
    std::vector<scene::Aabb> out(skin.joints.size());
    for (uint32_t v = 0; v < deformation.vertexCount; ++v) {
        const glm::vec3& p = vertices[deformation.firstVertex + v].position;
        for (uint32_t i = 0; i < deformation.influencesPerVertex; ++i) {
            const scene::JointInfluence& influence = deformation.influences[size_t(v) * deformation.influencesPerVertex + i];
            if (influence.weight > 0.0f && influence.joint < out.size()) out[influence.joint].extend(glm::vec3(p));
        }
    }
    return out;
}

glm::vec3 morphReach(const scene::Deformation& deformation, std::span<const float> weights) {
    glm::vec3 reach(0.0f);
    for (uint32_t t = 0; t < deformation.targetCount && t < weights.size(); ++t)
        reach += std::abs(weights[t]) * deformation.maxPositionDelta[t];
    return reach;
}

scene::Aabb skinnedBounds(std::span<const scene::Aabb> jointBounds, std::span<const glm::dmat4> joints, const glm::vec3& reach) {
    // Each box by its centre and half extent (Arvo): centre' = J c, half' = |J| h — the exact box of
    // the transformed corners, for one matrix product instead of eight.
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (size_t j = 0; j < jointBounds.size() && j < joints.size(); ++j) {
        if (!jointBounds[j].valid()) continue;
        const glm::dvec3 centre = 0.5 * (glm::dvec3(jointBounds[j].min) + glm::dvec3(jointBounds[j].max));
        const glm::dvec3 half = 0.5 * (glm::dvec3(jointBounds[j].max) - glm::dvec3(jointBounds[j].min)) + glm::dvec3(reach);
        const glm::dmat4& m = joints[j];
        const glm::dvec3 c = transformPoint(m, centre);
        const glm::dvec3 h = glm::abs(glm::dvec3(m[0])) * half.x + glm::abs(glm::dvec3(m[1])) * half.y + glm::abs(glm::dvec3(m[2])) * half.z;
        lo = glm::min(lo, c - h);
        hi = glm::max(hi, c + h);
    }
    scene::Aabb out;
    if (lo.x <= hi.x) out.extend(glm::vec3(lo)), out.extend(glm::vec3(hi));
    return out;
}

std::vector<scene::Vertex> deformVertices(const scene::Scene& scene, const scene::Draw& draw, std::span<const float> weights,
                                   std::span<const glm::dmat4> joints) {
    const scene::Deformation& d = scene.deformations[size_t(draw.deformation)];
    std::vector<scene::Vertex> out(d.vertexCount);
    for (uint32_t v = 0; v < d.vertexCount; ++v) {
        const scene::Vertex& base = scene.vertices[d.firstVertex + v];
        glm::dvec3 p(base.position), n(base.normal), t(base.tangent);
        glm::dvec4 uv(base.uv0, base.uv1), color(base.color);
        for (uint32_t target = 0; target < d.targetCount && target < weights.size(); ++target) {
            if (weights[target] == 0.0f) continue;
            const double w = weights[target];
            const scene::MorphDelta& delta = d.deltas[size_t(target) * d.vertexCount + v];
            p += w * glm::dvec3(delta.position);
            n += w * glm::dvec3(delta.normal);
            t += w * glm::dvec3(delta.tangent);
            uv += w * glm::dvec4(delta.uv);
            color += w * glm::dvec4(delta.color);
        }
        if (draw.skin >= 0) {
            glm::dmat4 m(0.0);
            for (uint32_t i = 0; i < d.influencesPerVertex; ++i) {
                const scene::JointInfluence& influence = d.influences[size_t(v) * d.influencesPerVertex + i];
                if (influence.weight > 0.0f) m += double(influence.weight) * joints[influence.joint];
            }
            p = transformPoint(m, p);
            n = cofactor(glm::dmat3(m)) * n;
            t = glm::dmat3(m) * t;
        }
        scene::Vertex& o = out[v];
        o.position = glm::vec3(p);
        o.normal = glm::vec3(unit(n));
        o.tangent = glm::vec4(glm::vec3(unit(t)), base.tangent.w);
        o.uv0 = glm::vec2(uv.x, uv.y);
        o.uv1 = glm::vec2(uv.z, uv.w);
        o.color = glm::vec4(color);
    }
    return out;
}

}  // namespace candela::pose
