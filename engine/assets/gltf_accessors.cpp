#include "assets/gltf_accessors.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

namespace candela::assets::gltf {
namespace {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");

// An accessor without a bufferView is all zeros, so nothing in the file bounds its count. Any real
// one (sparse values over a mesh's vertices) is no longer than the buffers that hold that mesh.
size_t maxUnbackedCount(const tinygltf::Model& model) {
    size_t bytes = 0;
    for (const tinygltf::Buffer& buffer : model.buffers) bytes += buffer.data.size();
    return std::max<size_t>(bytes, 65536);
}


int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT4: return 16;  // read by readFloats only (inverse bind matrices)
        default: return 0;
    }
}

// begin + stride * (count - 1) + size, or false on overflow. Precondition: count > 0.
bool rangeEnd(size_t begin, size_t stride, size_t count, size_t size, size_t& end) {
    size_t span = 0;
    return !__builtin_mul_overflow(stride, count - 1, &span) && !__builtin_add_overflow(begin, span, &end) &&
           !__builtin_add_overflow(end, size, &end);
}

template <typename T>
T load(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

float component(const uint8_t* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const float v = load<int8_t>(p);
            return normalized ? std::max(v / 127.0f, -1.0f) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? load<uint8_t>(p) / 255.0f : load<uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            const float v = load<int16_t>(p);
            return normalized ? std::max(v / 32767.0f, -1.0f) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return normalized ? load<uint16_t>(p) / 65535.0f : load<uint16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_INT: {
            const double v = load<int32_t>(p);
            return float(normalized ? std::max(v / 2147483647.0, -1.0) : v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            const double v = load<uint32_t>(p);
            return float(normalized ? v / 4294967295.0 : v);
        }
        default: return load<float>(p);
    }
}

uint32_t indexValue(const uint8_t* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<uint16_t>(p);
        default: return load<uint32_t>(p);
    }
}


// Reads every element of an accessor with `element(const uint8_t*)`, then applies sparse values.
template <typename T, typename Element>
std::vector<T> readElements(const LoadContext& ctx, const tinygltf::Model& model, int index, const std::string& what,
                            size_t elementSize, T zero, Element element) {
    const tinygltf::Accessor& accessor = model.accessors[size_t(index)];
    const std::string name = what + ": accessor " + std::to_string(index);
    const size_t count = accessor.count;
    std::vector<T> out;
    if (accessor.bufferView >= 0) {
        const std::span<const uint8_t> bytes = bufferViewBytes(ctx, model, accessor.bufferView, name);
        const size_t viewStride = model.bufferViews[size_t(accessor.bufferView)].byteStride;
        const size_t stride = viewStride ? viewStride : elementSize;
        if (stride < elementSize)
            ctx.fail(name + ": byteStride " + std::to_string(stride) + " is smaller than its element size " +
                     std::to_string(elementSize));
        if (count > 0) {
            size_t end = 0;
            if (!rangeEnd(accessor.byteOffset, stride, count, elementSize, end) || end > bytes.size())
                ctx.fail(name + ": byteOffset " + std::to_string(accessor.byteOffset) + " + " + std::to_string(count) +
                         " elements run past the end of bufferView " + std::to_string(accessor.bufferView) + " (" +
                         std::to_string(bytes.size()) + " bytes)");
        }
        out.reserve(count);
        for (size_t i = 0; i < count; ++i) out.push_back(element(bytes.data() + accessor.byteOffset + i * stride));
    } else {
        if (count > maxUnbackedCount(model))
            ctx.fail(name + ": count " + std::to_string(count) + " without a bufferView exceeds the file's data size");
        out.assign(count, zero);
    }
    if (!accessor.sparse.isSparse) return out;

    const auto& sparse = accessor.sparse;
    const std::string sparseName = name + " sparse";
    if (sparse.count <= 0 || size_t(sparse.count) > count)
        ctx.fail(sparseName + ": count " + std::to_string(sparse.count) + " not in [1, " + std::to_string(count) + "]");
    if (!isIndexType(sparse.indices.componentType))
        ctx.fail(sparseName + ": indices componentType " + std::to_string(sparse.indices.componentType) +
                 " is not an unsigned integer type");
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) ctx.fail(sparseName + ": negative byteOffset");
    const size_t sparseCount = size_t(sparse.count);
    const size_t indexSize = componentSize(sparse.indices.componentType);
    const auto indexBytes = bufferViewBytes(ctx, model, sparse.indices.bufferView, sparseName + " indices");
    const auto valueBytes = bufferViewBytes(ctx, model, sparse.values.bufferView, sparseName + " values");
    size_t indexEnd = 0, valueEnd = 0;
    if (!rangeEnd(size_t(sparse.indices.byteOffset), indexSize, sparseCount, indexSize, indexEnd) ||
        indexEnd > indexBytes.size())
        ctx.fail(sparseName + ": indices run past the end of bufferView " + std::to_string(sparse.indices.bufferView));
    if (!rangeEnd(size_t(sparse.values.byteOffset), elementSize, sparseCount, elementSize, valueEnd) ||
        valueEnd > valueBytes.size())
        ctx.fail(sparseName + ": values run past the end of bufferView " + std::to_string(sparse.values.bufferView));
    for (size_t i = 0; i < sparseCount; ++i) {
        const uint32_t target =
            indexValue(indexBytes.data() + size_t(sparse.indices.byteOffset) + i * indexSize, sparse.indices.componentType);
        if (target >= count)
            ctx.fail(sparseName + ": index " + std::to_string(target) + " >= count " + std::to_string(count));
        out[target] = element(valueBytes.data() + size_t(sparse.values.byteOffset) + i * elementSize);
    }
    return out;
}

}  // namespace

std::string typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "type " + std::to_string(type);
    }
}

size_t componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

bool isIndexType(int componentType) {
    return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

const tinygltf::Accessor& checkedAccessor(const LoadContext& ctx, const tinygltf::Model& model, int index,
                                          const std::string& what) {
    if (index < 0 || size_t(index) >= model.accessors.size())
        ctx.fail(what + ": accessor " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor& accessor = model.accessors[size_t(index)];
    if (componentSize(accessor.componentType) == 0)
        ctx.fail(what + ": accessor " + std::to_string(index) + " has unsupported componentType " +
                 std::to_string(accessor.componentType));
    return accessor;
}

std::span<const uint8_t> bufferViewBytes(const LoadContext& ctx, const tinygltf::Model& model, int view,
                                         const std::string& what) {
    if (view < 0 || size_t(view) >= model.bufferViews.size())
        ctx.fail(what + ": bufferView " + std::to_string(view) + " does not exist");
    const tinygltf::BufferView& bv = model.bufferViews[size_t(view)];
    if (bv.buffer < 0 || size_t(bv.buffer) >= model.buffers.size())
        ctx.fail(what + ": bufferView " + std::to_string(view) + " names buffer " + std::to_string(bv.buffer) +
                 ", which does not exist");
    const std::vector<unsigned char>& data = model.buffers[size_t(bv.buffer)].data;
    size_t end = 0;
    if (__builtin_add_overflow(bv.byteOffset, bv.byteLength, &end) || end > data.size())
        ctx.fail(what + ": bufferView " + std::to_string(view) + " [" + std::to_string(bv.byteOffset) + ", +" +
                 std::to_string(bv.byteLength) + ") lies outside buffer " + std::to_string(bv.buffer) + " (" +
                 std::to_string(data.size()) + " bytes)");
    return std::span<const uint8_t>(data.data() + bv.byteOffset, bv.byteLength);
}

size_t accessorCount(const LoadContext& ctx, const tinygltf::Model& model, int accessor, const std::string& what) {
    return checkedAccessor(ctx, model, accessor, what).count;
}

std::vector<glm::vec4> readVectors(const LoadContext& ctx, const tinygltf::Model& model, int index,
                                   std::initializer_list<int> types, const std::string& what) {
    const tinygltf::Accessor& accessor = checkedAccessor(ctx, model, index, what);
    if (std::find(types.begin(), types.end(), accessor.type) == types.end()) {
        std::string expected;
        for (int t : types) expected += (expected.empty() ? "" : " or ") + typeName(t);
        ctx.fail(what + ": accessor " + std::to_string(index) + " has type " + typeName(accessor.type) + ", expected " +
                 expected);
    }
    const int components = componentCount(accessor.type);
    const int componentType = accessor.componentType;
    const size_t size = componentSize(componentType);
    const bool normalized = accessor.normalized;
    return readElements<glm::vec4>(ctx, model, index, what, size * size_t(components), glm::vec4(0.0f),
                                   [&](const uint8_t* p) {
                                       glm::vec4 v(0.0f);
                                       for (int c = 0; c < components; ++c)
                                           v[c] = component(p + size_t(c) * size, componentType, normalized);
                                       return v;
                                   });
}

std::vector<float> readFloats(const LoadContext& ctx, const tinygltf::Model& model, int index, int type,
                              bool normalizedIntegers, const std::string& what) {
    const tinygltf::Accessor& accessor = checkedAccessor(ctx, model, index, what);
    const int componentType = accessor.componentType;
    const bool normalizedInteger = accessor.normalized && componentType != TINYGLTF_COMPONENT_TYPE_FLOAT &&
                                   componentSize(componentType) <= 2;
    if (accessor.type != type || (componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !(normalizedIntegers && normalizedInteger)))
        ctx.fail(what + ": accessor " + std::to_string(index) + " must be " + typeName(type) + " of FLOAT" +
                 (normalizedIntegers ? " or normalized (UNSIGNED_)BYTE/SHORT" : "") + ", not " + typeName(accessor.type) +
                 " of componentType " + std::to_string(componentType));
    const size_t components = size_t(componentCount(type));
    const size_t size = componentSize(componentType);
    using Element = std::array<float, 16>;
    const std::vector<Element> elements =
        readElements<Element>(ctx, model, index, what, size * components, Element{}, [&](const uint8_t* p) {
            Element e{};
            for (size_t c = 0; c < components; ++c) e[c] = component(p + c * size, componentType, accessor.normalized);
            return e;
        });
    std::vector<float> out;
    out.reserve(elements.size() * components);
    for (const Element& e : elements) out.insert(out.end(), e.begin(), e.begin() + std::ptrdiff_t(components));
    return out;
}

std::vector<uint32_t> readIndices(const LoadContext& ctx, const tinygltf::Model& model, int index,
                                  const std::string& what) {
    const tinygltf::Accessor& accessor = checkedAccessor(ctx, model, index, what);
    if (accessor.type != TINYGLTF_TYPE_SCALAR || !isIndexType(accessor.componentType))
        ctx.fail(what + ": index accessor " + std::to_string(index) +
                 " must be SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    const int componentType = accessor.componentType;
    return readElements<uint32_t>(ctx, model, index, what, componentSize(componentType), 0u,
                                  [&](const uint8_t* p) { return indexValue(p, componentType); });
}

}  // namespace candela::assets::gltf
