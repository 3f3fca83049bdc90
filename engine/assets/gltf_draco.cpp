#include "assets/gltf_draco.h"

#include "assets/gltf_accessors.h"

#include <draco/compression/decode.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <span>
#include <type_traits>

namespace candela::assets::gltf {
namespace {

constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";

// `value` in [0, 1] (unsigned C) or [-1, 1] (signed C) as a normalized integer, rounded.
template <typename C>
bool normalizedFromFloat(float value, C& out) {
    const float low = std::is_signed_v<C> ? -1.0f : 0.0f;
    if (!(value >= low && value <= 1.0f)) return false;
    out = C(std::lround(double(value) * double(std::numeric_limits<C>::max())));
    return true;
}

// Writes `count` values of `attribute` (point by point) as `components` values of C each. With
// `normalize`, float values become normalized integers (the accessor's `normalized`); otherwise
// Draco converts (range-checked; its own integers to floats by the attribute's normalized flag).
template <typename C>
bool convertAll(const draco::PointAttribute& attribute, uint32_t count, int components, bool normalize, uint8_t* out) {
    const bool fromFloat = attribute.data_type() == draco::DT_FLOAT32 || attribute.data_type() == draco::DT_FLOAT64;
    for (uint32_t point = 0; point < count; ++point) {
        const draco::AttributeValueIndex value = attribute.mapped_index(draco::PointIndex(point));
        if (value.value() >= attribute.size()) return false;
        C converted[4] = {};
        if constexpr (std::is_integral_v<C>) {
            if (normalize && fromFloat) {
                float floats[4] = {};
                if (!attribute.ConvertValue<float>(value, int8_t(components), floats)) return false;
                for (int c = 0; c < components; ++c)
                    if (!normalizedFromFloat(floats[c], converted[c])) return false;
            } else if (!attribute.ConvertValue<C>(value, int8_t(components), converted)) {
                return false;
            }
        } else if (!attribute.ConvertValue<C>(value, int8_t(components), converted)) {
            return false;
        }
        std::memcpy(out + size_t(point) * sizeof(C) * size_t(components), converted, sizeof(C) * size_t(components));
    }
    return true;
}

bool convertAttribute(const draco::PointAttribute& attribute, uint32_t count, const tinygltf::Accessor& accessor,
                      int components, uint8_t* out) {
    const bool n = accessor.normalized;
    switch (accessor.componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return convertAll<int8_t>(attribute, count, components, n, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return convertAll<uint8_t>(attribute, count, components, n, out);
        case TINYGLTF_COMPONENT_TYPE_SHORT: return convertAll<int16_t>(attribute, count, components, n, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return convertAll<uint16_t>(attribute, count, components, n, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return convertAll<uint32_t>(attribute, count, components, n, out);
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return convertAll<float>(attribute, count, components, false, out);
        default: return false;
    }
}

// The decoded data of one primitive, appended to a buffer of the model as tight, 4-byte aligned
// bufferViews with one accessor each.
class DecodedBuffer {
public:
    explicit DecodedBuffer(tinygltf::Model& model) : mModel(model) {}

    struct Slot {
        int accessor;   // index in model.accessors
        uint8_t* data;  // its bytes, to fill; valid until the next add()
    };

    // A new accessor like `like` (type, componentType, normalized, min/max) over `bytes` fresh bytes.
    Slot add(const tinygltf::Accessor& like, size_t count, size_t bytes) {
        tinygltf::BufferView view;
        view.buffer = bufferIndex();
        view.byteOffset = (mBytes.size() + 3) & ~size_t(3);
        view.byteLength = bytes;
        mBytes.resize(view.byteOffset + bytes);
        mModel.bufferViews.push_back(view);

        tinygltf::Accessor accessor;
        accessor.name = like.name;
        accessor.bufferView = int(mModel.bufferViews.size() - 1);
        accessor.byteOffset = 0;
        accessor.componentType = like.componentType;
        accessor.type = like.type;
        accessor.normalized = like.normalized;
        accessor.count = count;
        accessor.minValues = like.minValues;
        accessor.maxValues = like.maxValues;
        mModel.accessors.push_back(accessor);
        return {int(mModel.accessors.size() - 1), mBytes.data() + view.byteOffset};
    }

    // Moves the bytes into the model's new buffer.
    void finish() {
        tinygltf::Buffer buffer;
        buffer.name = "KHR_draco_mesh_compression (decoded)";
        buffer.data = std::move(mBytes);
        mModel.buffers.push_back(std::move(buffer));
    }

private:
    int bufferIndex() const { return int(mModel.buffers.size()); }

    tinygltf::Model& mModel;
    std::vector<uint8_t> mBytes;
};

// The compressed bytes the extension's bufferView names, range-checked.
std::span<const uint8_t> compressedBytes(const LoadContext& ctx, const tinygltf::Model& model,
                                         const tinygltf::Value& extension, const std::string& what) {
    const tinygltf::Value& view = extension.Get("bufferView");
    if (!view.IsInt()) ctx.fail(what + ": bufferView is missing");
    const std::span<const uint8_t> bytes = bufferViewBytes(ctx, model, view.GetNumberAsInt(), what);
    if (bytes.empty()) ctx.fail(what + ": its bufferView is empty");
    return bytes;
}

std::unique_ptr<draco::Mesh> decodeMesh(const LoadContext& ctx, std::span<const uint8_t> bytes, const std::string& what) {
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
    if (!type.ok()) ctx.fail(what + ": not a Draco stream (" + type.status().error_msg_string() + ")");
    if (type.value() != draco::TRIANGULAR_MESH) ctx.fail(what + ": the Draco stream is not a triangle mesh");
    draco::Decoder decoder;
    auto mesh = decoder.DecodeMeshFromBuffer(&buffer);
    if (!mesh.ok()) ctx.fail(what + ": Draco decoding failed (" + mesh.status().error_msg_string() + ")");
    return std::move(mesh).value();
}

void decodePrimitive(const LoadContext& ctx, tinygltf::Model& model, tinygltf::Primitive& primitive,
                     int indicesAccessor, const std::string& what) {
    const tinygltf::Value& extension = primitive.extensions.at(kDracoExtension);
    if (!extension.IsObject()) ctx.fail(what + ": not an object");
    const tinygltf::Value& attributes = extension.Get("attributes");
    if (!attributes.IsObject()) ctx.fail(what + ": attributes is missing or not an object");
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP)
        ctx.fail(what + ": mode " + std::to_string(primitive.mode) + " (Draco meshes are triangles or strips)");

    const std::unique_ptr<draco::Mesh> mesh = decodeMesh(ctx, compressedBytes(ctx, model, extension, what), what);
    const uint32_t points = mesh->num_points();
    const uint32_t faces = mesh->num_faces();
    DecodedBuffer out(model);

    // Indices: the decoded faces as a triangle list, in the file's index type when it has one.
    tinygltf::Accessor indexLike;
    indexLike.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    indexLike.type = TINYGLTF_TYPE_SCALAR;
    if (indicesAccessor >= 0) {
        indexLike = checkedAccessor(ctx, model, indicesAccessor, what + " indices");
        indexLike.minValues.clear();
        indexLike.maxValues.clear();
    }
    if (indexLike.type != TINYGLTF_TYPE_SCALAR || !isIndexType(indexLike.componentType))
        ctx.fail(what + ": the indices accessor is not an unsigned byte, short or int scalar");
    const size_t indexBytes = componentSize(indexLike.componentType);
    const uint64_t maxIndex = indexBytes == 4 ? std::numeric_limits<uint32_t>::max() : (uint64_t(1) << (8 * indexBytes)) - 1;
    if (primitive.mode == TINYGLTF_MODE_TRIANGLES && indicesAccessor >= 0 && indexLike.count != size_t(faces) * 3)
        ctx.fail(what + ": the indices accessor counts " + std::to_string(indexLike.count) + ", the Draco mesh has " +
                 std::to_string(size_t(faces) * 3));
    const DecodedBuffer::Slot indices = out.add(indexLike, size_t(faces) * 3, size_t(faces) * 3 * indexBytes);
    for (uint32_t f = 0; f < faces; ++f) {
        const draco::Mesh::Face& face = mesh->face(draco::FaceIndex(f));
        for (int corner = 0; corner < 3; ++corner) {
            const uint32_t index = face[corner].value();
            if (index >= points || index > maxIndex) ctx.fail(what + ": a decoded index is out of range");
            std::memcpy(indices.data + (size_t(f) * 3 + size_t(corner)) * indexBytes, &index, indexBytes);  // little-endian
        }
    }

    // Attributes the extension names, by their Draco unique ids.
    std::vector<std::pair<std::string, int>> replaced;
    for (const std::string& semantic : attributes.Keys()) {
        const std::string where = what + " attribute " + semantic;
        const tinygltf::Value& id = attributes.Get(semantic);
        if (!id.IsInt() || id.GetNumberAsInt() < 0) ctx.fail(where + ": the Draco attribute id is not an integer >= 0");
        const auto it = primitive.attributes.find(semantic);
        if (it == primitive.attributes.end()) ctx.fail(where + ": not among the primitive's attributes");
        // A copy: adding the decoded accessors below may reallocate model.accessors.
        const tinygltf::Accessor like = checkedAccessor(ctx, model, it->second, where);
        const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(uint32_t(id.GetNumberAsInt()));
        if (!attribute) ctx.fail(where + ": the Draco mesh has no attribute " + std::to_string(id.GetNumberAsInt()));
        if (like.count != points)
            ctx.fail(where + ": the accessor counts " + std::to_string(like.count) + ", the Draco mesh has " +
                     std::to_string(points) + " vertices");
        const int components = tinygltf::GetNumComponentsInType(uint32_t(like.type));
        const size_t bytes = componentSize(like.componentType);
        if (components < 1 || components > 4) ctx.fail(where + ": unsupported accessor type");
        if (attribute->num_components() != components)
            ctx.fail(where + ": the Draco attribute has " + std::to_string(attribute->num_components()) +
                     " components, the accessor " + std::to_string(components));
        if (!attribute->is_mapping_identity() && attribute->indices_map_size() < points)
            ctx.fail(where + ": the Draco attribute maps fewer vertices than the mesh has");
        const DecodedBuffer::Slot slot = out.add(like, points, size_t(points) * size_t(components) * bytes);
        if (!convertAttribute(*attribute, points, like, components, slot.data))
            ctx.fail(where + ": decoded values do not fit the accessor's component type");
        replaced.emplace_back(semantic, slot.accessor);
    }

    out.finish();
    primitive.indices = indices.accessor;
    for (const auto& [semantic, accessor] : replaced) primitive.attributes[semantic] = accessor;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.extensions.erase(kDracoExtension);
}

}  // namespace

bool detachDracoIndices(nlohmann::json& doc, DracoIndices& indices) {
    bool changed = false;
    const auto meshes = doc.find("meshes");
    if (meshes == doc.end()) return false;
    for (size_t m = 0; m < meshes->size(); ++m) {
        nlohmann::json& primitives = (*meshes)[m]["primitives"];
        for (size_t p = 0; p < primitives.size(); ++p) {
            nlohmann::json& primitive = primitives[p];
            const auto extensions = primitive.find("extensions");
            if (extensions == primitive.end() || !extensions->contains(kDracoExtension)) continue;
            const auto index = primitive.find("indices");
            if (index == primitive.end()) continue;
            indices[{m, p}] = index->get<int>();
            primitive.erase(index);
            changed = true;
        }
    }
    return changed;
}

size_t decodeDracoPrimitives(const LoadContext& ctx, tinygltf::Model& model, const DracoIndices& indices) {
    size_t decoded = 0;
    for (size_t m = 0; m < model.meshes.size(); ++m) {
        tinygltf::Mesh& mesh = model.meshes[m];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            tinygltf::Primitive& primitive = mesh.primitives[p];
            if (!primitive.extensions.count(kDracoExtension)) continue;
            const auto found = indices.find({m, p});
            decodePrimitive(ctx, model, primitive, found == indices.end() ? -1 : found->second,
                            label("mesh", int(m), mesh.name) + " primitive " + std::to_string(p) + " " + kDracoExtension);
            ++decoded;
        }
    }
    return decoded;
}

}  // namespace candela::assets::gltf
