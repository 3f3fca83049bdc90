#include "pose/shown_points.h"

#include "pose/skinning.h"

#include <algorithm>
#include <cmath>

namespace candela::pose {
namespace {

// Collects points and hands them on in batches of kBatch.
class Batcher {
public:
    explicit Batcher(const scene::PointBatch& visit) : mVisit(visit) { mPoints.reserve(kBatch); }
    ~Batcher() { flush(); }
    void add(const glm::vec3& p) {
        mPoints.push_back(p);
        if (mPoints.size() == kBatch) flush();
    }
    void flush() {
        if (!mPoints.empty()) mVisit(mPoints);
        mPoints.clear();
    }

private:
    static constexpr size_t kBatch = 4096;
    const scene::PointBatch& mVisit;
    std::vector<glm::vec3> mPoints;
};

// The morph weights of `draw`'s node in the rest pose (none for draws without a node).
std::span<const float> restWeights(const scene::Scene& scene, const scene::Draw& draw) {
    if (draw.node < 0 || size_t(draw.node) >= scene.nodes.size()) return {};
    return scene.nodes[size_t(draw.node)].weights;
}

}  // namespace

void visitDrawPoints(const scene::Scene& scene, const scene::Draw& draw, std::span<const float> weights,
                     std::span<const glm::dmat4> joints, const scene::PointBatch& visit) {
    Batcher out(visit);
    if (draw.deformation >= 0) {
        const scene::Deformation& d = scene.deformations[size_t(draw.deformation)];
        const uint32_t targets = std::min<uint32_t>(d.targetCount, uint32_t(weights.size()));
        const bool skinned = draw.skin >= 0;
        const std::span<const glm::mat4> instances =
            draw.instanceCount ? std::span(scene.instances).subspan(draw.firstInstance, draw.instanceCount)
                               : std::span<const glm::mat4>();
        for (uint32_t v = 0; v < d.vertexCount; ++v) {
            glm::vec3 p = scene.vertices[d.firstVertex + v].position;
            for (uint32_t t = 0; t < targets; ++t)
                if (weights[t] != 0.0f) p += weights[t] * glm::vec3(d.deltas[size_t(t) * d.vertexCount + v].position);
            if (skinned) {
                glm::dmat4 m(0.0);
                for (uint32_t i = 0; i < d.influencesPerVertex; ++i) {
                    const scene::JointInfluence& influence = d.influences[size_t(v) * d.influencesPerVertex + i];
                    if (influence.weight > 0.0f && influence.joint < joints.size()) m += double(influence.weight) * joints[influence.joint];
                }
                out.add(glm::vec3(m * glm::dvec4(p, 1.0)));
            } else if (instances.empty()) {
                out.add(glm::vec3(draw.world * glm::vec4(p, 1.0f)));
            } else {
                for (const glm::mat4& instance : instances) out.add(glm::vec3(draw.world * (instance * glm::vec4(p, 1.0f))));
            }
        }
        return;
    }
    if (draw.indexCount == 0) return;
    const auto [lo, hi] = std::minmax_element(scene.indices.begin() + draw.firstIndex,
                                              scene.indices.begin() + draw.firstIndex + draw.indexCount);
    const std::span<const scene::Vertex> vertices(scene.vertices.data() + *lo, size_t(*hi - *lo) + 1);
    if (draw.instanceCount == 0) {
        for (const scene::Vertex& v : vertices) out.add(glm::vec3(draw.world * glm::vec4(v.position, 1.0f)));
        return;
    }
    for (const glm::mat4& instance : std::span(scene.instances).subspan(draw.firstInstance, draw.instanceCount)) {
        const glm::mat4 m = draw.world * instance;
        for (const scene::Vertex& v : vertices) out.add(glm::vec3(m * glm::vec4(v.position, 1.0f)));
    }
}

void visitShownPoints(const scene::Scene& scene, const scene::PointBatch& visit, bool includeHidden) {
    std::vector<std::vector<glm::dmat4>> joints(scene.skins.size());
    for (const scene::Draw& draw : scene.draws) {
        if (draw.hidden && !includeHidden) continue;
        if (draw.skin >= 0 && joints[size_t(draw.skin)].empty())
            jointMatrices(scene.skins[size_t(draw.skin)], scene.nodes, joints[size_t(draw.skin)]);
        visitDrawPoints(scene, draw, restWeights(scene, draw), draw.skin >= 0 ? std::span(joints[size_t(draw.skin)]) : std::span<const glm::dmat4>(),
                        visit);
    }
}

void visitShownPoints(const ScenePose& pose, const scene::PointBatch& visit) {
    const scene::Scene& scene = pose.scene();
    for (const scene::Draw& draw : pose.draws()) {
        if (draw.hidden) continue;
        visitDrawPoints(scene, draw, pose.weights(draw),
                        draw.skin >= 0 ? std::span(pose.jointMatrices(uint32_t(draw.skin))) : std::span<const glm::dmat4>(), visit);
    }
}

scene::Aabb shownBounds(const scene::Scene& scene, bool includeHidden) {
    scene::Aabb box;
    visitShownPoints(scene, [&](std::span<const glm::vec3> batch) {
        for (const glm::vec3& p : batch) box.extend(p);
    }, includeHidden);
    return box;
}

scene::PointSource shownPoints(const scene::Scene& scene, const ScenePose* pose, std::vector<double> times, bool loop) {
    if (pose && !pose->movesNodes()) pose = nullptr;
    if (!pose) return [&scene](const scene::PointBatch& visit) { visitShownPoints(scene, visit); };
    if (times.empty()) return [pose](const scene::PointBatch& visit) { visitShownPoints(*pose, visit); };
    return [pose, times = std::move(times), loop](const scene::PointBatch& visit) {
        ScenePose at = *pose;
        for (double t : times) {
            at.evaluate(t, loop);
            visitShownPoints(at, visit);
        }
    };
}

std::vector<double> animationTimes(const ScenePose& pose, size_t maxTimes) {
    const scene::Scene& scene = pose.scene();
    const double duration = pose.duration();
    std::vector<double> times{0.0};
    for (uint32_t a : pose.playing())
        for (const animation::AnimationChannel& channel : scene.animations[a].channels)
            for (float t : scene.animations[a].samplers[channel.sampler].times) times.push_back(double(t));
    constexpr double kStep = 1.0 / 30.0;
    for (double t = kStep; t < duration; t += kStep) times.push_back(t);
    times.push_back(duration);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    if (times.size() > maxTimes && maxTimes >= 2) {
        times.clear();
        for (size_t i = 0; i < maxTimes; ++i) times.push_back(duration * double(i) / double(maxTimes - 1));
    }
    return times;
}

}  // namespace candela::pose
