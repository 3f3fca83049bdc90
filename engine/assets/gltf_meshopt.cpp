#include "assets/gltf_meshopt.h"

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace candela::assets::gltf {
namespace {

constexpr const char* kMeshoptExtension = "EXT_meshopt_compression";

// The most decoded bytes meshoptimizer's codecs produce per compressed byte: the attribute codec
// spends at least 2 header bits on 16 bytes (a group of one byte column whose deltas are all zero),
// the index codecs at least a byte per triangle or index. Anything claiming more is malformed, and
// is refused before the decoded size is allocated.
constexpr uint64_t kMaxExpansion = 64;
constexpr uint64_t kExpansionSlack = 4096;

struct Compressed {
    int buffer = -1;
    uint64_t byteOffset = 0;
    uint64_t byteLength = 0;
    uint64_t byteStride = 0;
    uint64_t count = 0;
    std::string mode;
    std::string filter = "NONE";
};

// An integer property of the extension object, >= 0; nullopt when absent.
std::optional<uint64_t> number(const LoadContext& ctx, const tinygltf::Value& object, const char* key,
                               const std::string& what) {
    if (!object.Has(key)) return std::nullopt;
    const tinygltf::Value& value = object.Get(key);
    const double v = value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
    if (!(v >= 0.0 && v <= 1e15 && std::floor(v) == v)) ctx.fail(what + ": " + key + " is not an integer >= 0");
    return uint64_t(v);
}

Compressed readExtension(const LoadContext& ctx, const tinygltf::Value& object, const std::string& what) {
    if (!object.IsObject()) ctx.fail(what + ": not an object");
    Compressed c;
    auto required = [&](const char* key) {
        const std::optional<uint64_t> v = number(ctx, object, key, what);
        if (!v) ctx.fail(what + ": " + key + " is missing");
        return *v;
    };
    c.buffer = int(std::min<uint64_t>(required("buffer"), uint64_t(INT32_MAX)));
    c.byteOffset = number(ctx, object, "byteOffset", what).value_or(0);
    c.byteLength = required("byteLength");
    c.byteStride = required("byteStride");
    c.count = required("count");
    if (!object.Get("mode").IsString()) ctx.fail(what + ": mode is missing");
    c.mode = object.Get("mode").Get<std::string>();
    if (object.Has("filter")) {
        if (!object.Get("filter").IsString()) ctx.fail(what + ": filter is not a string");
        c.filter = object.Get("filter").Get<std::string>();
    }
    return c;
}

// The specification's validity rules for the extension object on `view`.
void checkRules(const LoadContext& ctx, const Compressed& c, const tinygltf::BufferView& view, const std::string& what) {
    const std::string stride = std::to_string(c.byteStride);
    if (c.mode != "ATTRIBUTES" && c.mode != "TRIANGLES" && c.mode != "INDICES")
        ctx.fail(what + ": unknown mode '" + c.mode + "'");
    if (c.filter != "NONE" && c.filter != "OCTAHEDRAL" && c.filter != "QUATERNION" && c.filter != "EXPONENTIAL")
        ctx.fail(what + ": unknown filter '" + c.filter + "'");
    if (view.byteStride != 0 && uint64_t(view.byteStride) != c.byteStride)
        ctx.fail(what + ": byteStride " + stride + " differs from the bufferView's " + std::to_string(view.byteStride));
    if (c.byteStride == 0 || c.count > UINT64_MAX / c.byteStride || uint64_t(view.byteLength) != c.count * c.byteStride)
        ctx.fail(what + ": the bufferView's byteLength " + std::to_string(view.byteLength) + " is not count " +
                 std::to_string(c.count) + " × byteStride " + stride);
    if (c.mode == "ATTRIBUTES" && (c.byteStride % 4 != 0 || c.byteStride > 256))
        ctx.fail(what + ": ATTRIBUTES need a byteStride divisible by 4 and at most 256, not " + stride);
    if (c.mode != "ATTRIBUTES") {
        if (c.byteStride != 2 && c.byteStride != 4) ctx.fail(what + ": " + c.mode + " need a byteStride of 2 or 4, not " + stride);
        if (c.filter != "NONE") ctx.fail(what + ": " + c.mode + " take no filter ('" + c.filter + "')");
        if (c.mode == "TRIANGLES" && c.count % 3 != 0) ctx.fail(what + ": TRIANGLES count " + std::to_string(c.count) + " is not a multiple of 3");
    }
    if (c.filter == "OCTAHEDRAL" && c.byteStride != 4 && c.byteStride != 8)
        ctx.fail(what + ": OCTAHEDRAL needs a byteStride of 4 or 8, not " + stride);
    if (c.filter == "QUATERNION" && c.byteStride != 8) ctx.fail(what + ": QUATERNION needs a byteStride of 8, not " + stride);
    if (c.filter == "EXPONENTIAL" && c.byteStride % 4 != 0)
        ctx.fail(what + ": EXPONENTIAL needs a byteStride divisible by 4, not " + stride);
}

// Decodes `source` into `out` (count × byteStride bytes) and applies the filter.
void decode(const LoadContext& ctx, const Compressed& c, std::span<const uint8_t> source, uint8_t* out,
            const std::string& what) {
    const size_t count = size_t(c.count), stride = size_t(c.byteStride);
    int result = 0;
    if (c.mode == "ATTRIBUTES") result = meshopt_decodeVertexBuffer(out, count, stride, source.data(), source.size());
    else if (c.mode == "TRIANGLES") result = meshopt_decodeIndexBuffer(out, count, stride, source.data(), source.size());
    else result = meshopt_decodeIndexSequence(out, count, stride, source.data(), source.size());
    if (result != 0)
        ctx.fail(what + ": the " + c.mode + " data does not decode (meshoptimizer error " + std::to_string(result) + ")");
    if (c.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out, count, stride);
    else if (c.filter == "QUATERNION") meshopt_decodeFilterQuat(out, count, stride);
    else if (c.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out, count, stride);
}

}  // namespace

bool emptyMeshoptFallbackBuffers(nlohmann::json& doc, bool binary) {
    const auto used = doc.find("extensionsUsed");
    if (used == doc.end() || std::find(used->begin(), used->end(), kMeshoptExtension) == used->end()) return false;
    const auto buffers = doc.find("buffers");
    if (buffers == doc.end()) return false;
    bool changed = false;
    for (size_t i = 0; i < buffers->size(); ++i) {
        nlohmann::json& buffer = (*buffers)[i];
        const bool binChunk = binary && i == 0 && !buffer.contains("uri");
        const nlohmann::json* ext = nullptr;
        if (const auto e = buffer.find("extensions"); e != buffer.end() && e->contains(kMeshoptExtension)) ext = &(*e)[kMeshoptExtension];
        const bool fallback = ext && ext->is_object() && ext->value("fallback", false);
        if (binChunk || (buffer.contains("uri") && !fallback)) continue;
        buffer["uri"] = "data:application/octet-stream;base64,AAAA";  // 3 bytes: tinygltf refuses none
        buffer["byteLength"] = 3;
        changed = true;
    }
    return changed;
}

size_t decodeMeshoptBufferViews(const LoadContext& ctx, tinygltf::Model& model) {
    std::vector<uint8_t> decoded;
    std::vector<std::pair<size_t, uint64_t>> moved;  // view index, offset in `decoded`
    for (size_t v = 0; v < model.bufferViews.size(); ++v) {
        tinygltf::BufferView& view = model.bufferViews[v];
        const auto found = view.extensions.find(kMeshoptExtension);
        if (found == view.extensions.end()) continue;
        const std::string what = label("bufferView", int(v), view.name) + " " + kMeshoptExtension;
        const Compressed c = readExtension(ctx, found->second, what);
        checkRules(ctx, c, view, what);
        if (size_t(c.buffer) >= model.buffers.size()) ctx.fail(what + ": buffer " + std::to_string(c.buffer) + " does not exist");
        const std::vector<unsigned char>& data = model.buffers[size_t(c.buffer)].data;
        if (c.byteOffset > data.size() || c.byteLength > data.size() - c.byteOffset)
            ctx.fail(what + ": its data (" + std::to_string(c.byteLength) + " bytes at " + std::to_string(c.byteOffset) +
                     ") lies outside buffer " + std::to_string(c.buffer) + " (" + std::to_string(data.size()) + " bytes)");
        const uint64_t bytes = c.count * c.byteStride;
        if (bytes > kMaxExpansion * c.byteLength + kExpansionSlack)
            ctx.fail(what + ": " + std::to_string(c.byteLength) + " compressed bytes cannot hold the " +
                     std::to_string(bytes) + " bytes it claims");
        const uint64_t offset = (decoded.size() + 3) & ~uint64_t(3);
        decoded.resize(size_t(offset + bytes));
        decode(ctx, c, {data.data() + c.byteOffset, size_t(c.byteLength)}, decoded.data() + offset, what);
        moved.emplace_back(v, offset);
    }
    if (moved.empty()) return 0;
    tinygltf::Buffer buffer;
    buffer.name = "EXT_meshopt_compression (decoded)";
    buffer.data = std::move(decoded);
    model.buffers.push_back(std::move(buffer));
    for (const auto& [v, offset] : moved) {
        tinygltf::BufferView& view = model.bufferViews[v];
        view.buffer = int(model.buffers.size() - 1);
        view.byteOffset = size_t(offset);
        view.extensions.erase(kMeshoptExtension);
    }
    return moved.size();
}

}  // namespace candela::assets::gltf
