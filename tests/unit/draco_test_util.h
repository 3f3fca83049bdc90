#pragma once
// KHR_draco_mesh_compression inputs for the loader tests and the bad-input catalogue: a quad
// encoded with Draco's own encoder (sequential, no quantization, so the decoded values and vertex
// order equal the input), written as the extension asks — accessors without bufferViews, the
// stream in its own bufferView.

#include "gltf_test_util.h"

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

namespace candela::assets::test {

struct DracoQuad {
    std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    std::vector<float> normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    std::vector<float> uvs = {0, 1, 1, 1, 1, 0, 0, 0};
    std::vector<uint16_t> indices = {0, 1, 2, 0, 2, 3};

    // The Draco stream of the quad: attribute ids 0 POSITION, 1 NORMAL, 2 TEXCOORD_0.
    Bytes encode() const {
        const uint32_t points = uint32_t(positions.size() / 3);
        draco::Mesh mesh;
        mesh.set_num_points(points);
        auto add = [&](draco::GeometryAttribute::Type type, const std::vector<float>& values, int components) {
            draco::GeometryAttribute attribute;
            attribute.Init(type, nullptr, uint8_t(components), draco::DT_FLOAT32, false,
                           int64_t(sizeof(float)) * components, 0);
            const int id = mesh.AddAttribute(attribute, true, points);
            for (uint32_t i = 0; i < points; ++i)
                mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(i), &values[size_t(i) * size_t(components)]);
        };
        add(draco::GeometryAttribute::POSITION, positions, 3);
        add(draco::GeometryAttribute::NORMAL, normals, 3);
        add(draco::GeometryAttribute::TEX_COORD, uvs, 2);
        for (size_t i = 0; i < indices.size(); i += 3)
            mesh.AddFace({draco::PointIndex(indices[i]), draco::PointIndex(indices[i + 1]), draco::PointIndex(indices[i + 2])});
        draco::Encoder encoder;
        encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
        draco::EncoderBuffer buffer;
        const draco::Status status = encoder.EncodeMeshToBuffer(mesh, &buffer);
        if (!status.ok()) throw std::runtime_error("Draco encoding failed: " + status.error_msg_string());
        return Bytes(buffer.data(), buffer.data() + buffer.size());
    }

    // The quad as plain accessors (the reference a Draco load must match).
    GltfBuilder plain() const {
        GltfBuilder b;
        const Json attributes = {{"POSITION", b.addFloats(positions, "VEC3", 3)},
                                 {"NORMAL", b.addFloats(normals, "VEC3", 3)},
                                 {"TEXCOORD_0", b.addFloats(uvs, "VEC2", 2)}};
        b.setScene({b.addNode({{"mesh", b.addMesh(attributes, b.addIndices(indices))}})});
        return b;
    }

    // The quad compressed: `stream` (encode() unless given) in a bufferView, accessors without data.
    GltfBuilder compressed(const Bytes& stream = {}) const {
        const Bytes bytes = stream.empty() ? encode() : stream;
        GltfBuilder b;
        const int view = b.addView(bytes.data(), bytes.size());
        const size_t points = positions.size() / 3;
        const Json attributes = {{"POSITION", b.addAccessor(-1, kFloat, points, "VEC3")},
                                 {"NORMAL", b.addAccessor(-1, kFloat, points, "VEC3")},
                                 {"TEXCOORD_0", b.addAccessor(-1, kFloat, points, "VEC2")}};
        const int mesh = b.addMesh(attributes, b.addAccessor(-1, kUnsignedShort, indices.size(), "SCALAR"));
        b.doc["meshes"][mesh]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"] = {
            {"bufferView", view}, {"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}}};
        b.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
        b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
        b.setScene({b.addNode({{"mesh", mesh}})});
        return b;
    }
};

}  // namespace candela::assets::test
