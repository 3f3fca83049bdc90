#pragma once
// EXT_meshopt_compression inputs for the loader tests, the bad-input catalogue and the fuzz seeds:
// bufferViews encoded with meshoptimizer's own encoders and filters, written either compressed
// (the stream in buffer 0, the view itself in a placeholder buffer without a URI, marked as
// fallback) or plain with exactly the bytes a decoder must produce, so a test can require equality.

#include "gltf_test_util.h"

#include <meshoptimizer.h>

namespace candela::assets::test {

// One bufferView's data: `decoded` is what a loader must end up with; `filtered` what goes into
// the codec (equal to `decoded` without a filter).
struct MeshoptView {
    Bytes decoded, filtered;
    size_t count = 0, stride = 0;
    std::string mode = "ATTRIBUTES", filter = "NONE";
};

inline MeshoptView meshoptAttributes(const void* data, size_t count, size_t stride) {
    MeshoptView v{.count = count, .stride = stride};
    v.decoded.assign(static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + count * stride);
    v.filtered = v.decoded;
    return v;
}
template <typename T>
MeshoptView meshoptAttributes(const std::vector<T>& values, size_t components) {
    return meshoptAttributes(values.data(), values.size() / components, components * sizeof(T));
}

// `values` (count × stride/4 floats, or 4 per element for OCTAHEDRAL) through `filter`'s encoder
// (what the codec compresses) and its decoder (what a loader must end up with).
inline MeshoptView meshoptFiltered(const std::vector<float>& values, size_t count, size_t stride, const char* filter,
                                   int bits, void (*encode)(void*, size_t, size_t, int, const float*),
                                   void (*decode)(void*, size_t, size_t)) {
    MeshoptView v{.count = count, .stride = stride, .filter = filter};
    v.filtered.resize(count * stride);
    encode(v.filtered.data(), count, stride, bits, values.data());
    v.decoded = v.filtered;
    decode(v.decoded.data(), count, stride);
    return v;
}

// Unit vectors (x, y, z, w per element) through the OCTAHEDRAL filter: normalized bytes (stride 4).
inline MeshoptView meshoptOctahedral(const std::vector<float>& xyzw, int bits = 8) {
    return meshoptFiltered(xyzw, xyzw.size() / 4, 4, "OCTAHEDRAL", bits, meshopt_encodeFilterOct, meshopt_decodeFilterOct);
}

// Unit quaternions (x, y, z, w) through the QUATERNION filter: normalized shorts (stride 8).
inline MeshoptView meshoptQuaternion(const std::vector<float>& xyzw, int bits = 12) {
    return meshoptFiltered(xyzw, xyzw.size() / 4, 8, "QUATERNION", bits, meshopt_encodeFilterQuat, meshopt_decodeFilterQuat);
}

// Floats (`components` per element) through the EXPONENTIAL filter: floats again (stride 4 × components).
inline MeshoptView meshoptExponential(const std::vector<float>& values, size_t components, int bits = 16) {
    return meshoptFiltered(values, values.size() / components, 4 * components, "EXPONENTIAL", bits,
                           meshopt_encodeFilterExp, meshopt_decodeFilterExp);
}

// Unsigned short indices, as TRIANGLES (a triangle list) or INDICES (any sequence).
inline MeshoptView meshoptIndices(const std::vector<uint16_t>& indices, const std::string& mode = "TRIANGLES") {
    MeshoptView v = meshoptAttributes(indices.data(), indices.size(), 2);
    v.mode = mode;
    return v;
}

// The compressed stream of `v`.
inline Bytes meshoptEncode(const MeshoptView& v) {
    Bytes out;
    if (v.mode == "ATTRIBUTES") {
        out.resize(meshopt_encodeVertexBufferBound(v.count, v.stride));
        out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), v.filtered.data(), v.count, v.stride));
        return out;
    }
    std::vector<unsigned int> indices(v.count);
    uint32_t vertices = 0;
    for (size_t i = 0; i < v.count; ++i) {
        indices[i] = v.stride == 2 ? uint32_t(v.decoded[2 * i] | v.decoded[2 * i + 1] << 8)
                                   : uint32_t(v.decoded[4 * i]) | uint32_t(v.decoded[4 * i + 1]) << 8 |
                                         uint32_t(v.decoded[4 * i + 2]) << 16 | uint32_t(v.decoded[4 * i + 3]) << 24;
        vertices = std::max(vertices, indices[i] + 1);
    }
    if (v.mode == "TRIANGLES") {
        out.resize(meshopt_encodeIndexBufferBound(v.count, vertices));
        out.resize(meshopt_encodeIndexBuffer(out.data(), out.size(), indices.data(), v.count));
    } else {
        out.resize(meshopt_encodeIndexSequenceBound(v.count, vertices));
        out.resize(meshopt_encodeIndexSequence(out.data(), out.size(), indices.data(), v.count));
    }
    return out;
}

// Adds `v` to `b` as a bufferView, compressed or plain; returns the view's index. Compressed views
// live in buffer 1, a placeholder without a URI ("fallback": true) that grows with each view; their
// streams in buffer 0. `byteStride` is written for attributes (as glTF wants for vertex data).
inline int addMeshoptView(GltfBuilder& b, const MeshoptView& v, bool compress, bool vertexData = true) {
    const int stride = v.mode == "ATTRIBUTES" && vertexData ? int(v.stride) : 0;
    if (!compress) return b.addView(v.decoded.data(), v.decoded.size(), stride);
    const Bytes stream = meshoptEncode(v);
    const int streamView = b.addView(stream.data(), stream.size());
    const Json source = b.doc["bufferViews"][streamView];
    b.doc["bufferViews"].erase(size_t(streamView));  // the stream is addressed by the extension, not a view
    if (b.moreBuffers.empty())
        b.moreBuffers.push_back({{"byteLength", 0}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    Json& fallback = b.moreBuffers[0];
    const size_t offset = (fallback["byteLength"].get<size_t>() + 3) & ~size_t(3);
    fallback["byteLength"] = offset + v.decoded.size();
    Json view = {{"buffer", 1}, {"byteOffset", offset}, {"byteLength", v.decoded.size()}};
    if (stride) view["byteStride"] = stride;
    view["extensions"]["EXT_meshopt_compression"] = {{"buffer", 0},
                                                     {"byteOffset", source["byteOffset"]},
                                                     {"byteLength", stream.size()},
                                                     {"byteStride", v.stride},
                                                     {"count", v.count},
                                                     {"mode", v.mode}};
    if (v.filter != "NONE") view["extensions"]["EXT_meshopt_compression"]["filter"] = v.filter;
    b.doc["bufferViews"].push_back(view);
    b.doc["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    b.doc["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    return int(b.doc["bufferViews"].size() - 1);
}

// A quad with float positions, octahedral byte normals, normalized short texture coordinates and
// a triangle list, every view compressed or every view plain (the reference).
inline GltfBuilder meshoptQuad(bool compress) {
    GltfBuilder b;
    const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const std::vector<float> normals = {0, 0, 1, 0, 0.6f, 0, 0.8f, 0, 0, 0.6f, 0.8f, 0, -0.6f, 0, 0.8f, 0};
    const std::vector<uint16_t> uvs = {0, 65535, 65535, 65535, 65535, 0, 0, 0};
    const int pos = b.addAccessor(addMeshoptView(b, meshoptAttributes(positions, 3), compress), kFloat, 4, "VEC3");
    const int nrm = b.addAccessor(addMeshoptView(b, meshoptOctahedral(normals), compress), kByte, 4, "VEC3", true);
    const int uv = b.addAccessor(addMeshoptView(b, meshoptAttributes(uvs, 2), compress), kUnsignedShort, 4, "VEC2", true);
    const int idx = b.addAccessor(addMeshoptView(b, meshoptIndices({0, 1, 2, 0, 2, 3}), compress, false),
                                  kUnsignedShort, 6, "SCALAR");
    b.doc["extensionsUsed"] = compress ? Json{"EXT_meshopt_compression", "KHR_mesh_quantization"} : Json{"KHR_mesh_quantization"};
    b.doc["extensionsRequired"] = b.doc["extensionsUsed"];
    const int mesh = b.addMesh({{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}, idx);
    b.setScene({b.addNode({{"mesh", mesh}})});
    return b;
}

}  // namespace candela::assets::test
