#pragma once
// Comparisons the compressed-geometry tests (Draco, meshopt) share: a compressed file against its
// plain version, exactly (lossless test inputs) or within a stated share of the model's size
// (quantized real files), at rest and posed; and the one-line error of a malformed file.

#include "bad_input_expect.h"
#include "gltf_test_util.h"

#include "pose/scene_pose.h"

#include <cstdlib>

namespace candela::assets::test {

// Same draws, indices and vertex positions, normals and texture coordinates, to the bit.
inline void expectSameGeometry(const scene::Scene& a, const scene::Scene& b) {
    ASSERT_EQ(a.draws.size(), b.draws.size());
    ASSERT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (size_t i = 0; i < a.vertices.size(); ++i) {
        EXPECT_EQ(a.vertices[i].position, b.vertices[i].position) << "vertex " << i;
        EXPECT_EQ(a.vertices[i].normal, b.vertices[i].normal) << "vertex " << i;
        EXPECT_EQ(a.vertices[i].uv0, b.vertices[i].uv0) << "vertex " << i;
    }
}

// Every face of `a` within `tolerance` × the diagonal of `reference` of the same face of `reference`.
inline void expectBoundsNear(const scene::Aabb& a, const scene::Aabb& reference, float tolerance, const std::string& where = "") {
    const float extent = glm::length(reference.max - reference.min);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(a.min[axis], reference.min[axis], tolerance * extent) << where << " axis " << axis;
        EXPECT_NEAR(a.max[axis], reference.max[axis], tolerance * extent) << where << " axis " << axis;
    }
}

// The scene bounds of `a` and `b`, posed by `animations` (as --animation) at each of `times`, agree
// within `tolerance` of the extent.
inline void expectSamePosedBounds(const scene::Scene& a, const scene::Scene& b, const std::vector<std::string>& animations,
                                  float tolerance, std::initializer_list<double> times) {
    pose::ScenePose pa(a, pose::selectAnimations(a, animations)), pb(b, pose::selectAnimations(b, animations));
    for (double time : times) {
        pa.evaluate(time);
        pb.evaluate(time);
        expectBoundsNear(pa.bounds(), pb.bounds(), tolerance, "t " + std::to_string(time));
    }
}

// Runs the reference meshopt encoder: `gltfpack -cc` (Debian's gltfpack, meshoptimizer 0.18:
// every view compressed, positions 14-bit, texture coordinates 12-bit, normals 8-bit octahedral,
// animations resampled at 30 Hz with quaternion/exponential filters, a placeholder buffer without a
// URI). Fails the test when it does not run (tools/install-deps.sh installs gltfpack).
inline void gltfpack(const fs::path& input, const fs::path& output) {
    const std::string command = "gltfpack -cc -i '" + input.string() + "' -o '" + output.string() + "' >/dev/null 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command << " (tools/install-deps.sh installs gltfpack)";
}

// Loading `file` fails with one line naming it and containing `fragment`.
inline void expectLoadFails(const fs::path& file, const std::string& fragment) {
    std::string message;
    try {
        assets::loadGltf(file);
    } catch (const UserError& e) {
        message = e.what();
    }
    candela::test::expectOneLineErrorNamingFile(file, message, fragment);
}

}  // namespace candela::assets::test
