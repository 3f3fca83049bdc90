#include "assets/gltf_file.h"

#include "assets/gltf_draco.h"
#include "assets/gltf_meshopt.h"
#include "assets/gltf_schema.h"
#include "core/errors.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <exception>
#include <fstream>
#include <limits>
#include <optional>
#include <string_view>

namespace candela::assets::gltf {
namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;     // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;      // "BIN\0"
constexpr size_t kMaxMessage = 300;             // tinygltf/nlohmann messages can quote the input
// tinygltf converts "extras"/"extensions" JSON recursively: deep nesting would overflow the stack.
constexpr int kMaxJsonDepth = 512;

uint32_t readU32(const uint8_t* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

void appendU32(std::vector<uint8_t>& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
}

// The deepest nesting of arrays and objects in `json` (strings skipped), stopping past `limit`.
int jsonDepth(std::string_view json, int limit) {
    int depth = 0, deepest = 0;
    bool inString = false, escaped = false;
    for (char c : json) {
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
            if (deepest > limit) break;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

// Shortens "data:...;base64,AAAA...." inside a message to its first few characters.
std::string shortenDataUris(std::string text) {
    for (size_t at = text.find(";base64,"); at != std::string::npos; at = text.find(";base64,", at + 1)) {
        const size_t begin = at + 8;
        size_t end = begin;
        while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '+' ||
                                     text[end] == '/' || text[end] == '='))
            ++end;
        if (end - begin > 16) text.replace(begin + 16, end - begin - 16, "...");
    }
    return text;
}

// tinygltf's messages are multi-line and name absolute paths; ours are one line, relative to the model.
std::string oneLine(std::string text, const std::string& base) {
    text = shortenDataUris(std::move(text));
    for (size_t at = text.find(base); !base.empty() && at != std::string::npos; at = text.find(base, at))
        text.erase(at, base.size());
    std::string out;
    for (char c : text) {
        if (c == '\n' || c == '\r') {
            if (!out.empty() && out.back() != ' ') out += "; ";
        } else if (static_cast<unsigned char>(c) >= 0x20) {
            out += c;
        }
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
    if (out.size() > kMaxMessage) out = out.substr(0, kMaxMessage) + "...";
    return out.empty() ? std::string("unknown error") : out;
}

}  // namespace

std::vector<uint8_t> readGltfFile(const LoadContext& ctx, const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) ctx.fail("is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) ctx.fail(std::string("cannot open: ") + std::strerror(errno));
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) ctx.fail("cannot read");
    if (size == 0) ctx.fail("empty file");
    // tinygltf takes lengths as unsigned int.
    if (static_cast<uint64_t>(size) >= std::numeric_limits<uint32_t>::max()) ctx.fail("file larger than 4 GiB");
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), size)) ctx.fail("read error");
    return bytes;
}

namespace {

// The chunks of a GLB container, borrowed from the file.
struct GlbChunks {
    std::string_view json;
    std::span<const uint8_t> bin;  // empty when there is no BIN chunk
};

// Checks the GLB container and returns its JSON and BIN chunks.
GlbChunks readGlb(const LoadContext& ctx, std::span<const uint8_t> file) {
    if (file.size() < 12) ctx.fail("truncated GLB: " + std::to_string(file.size()) + " bytes, the header needs 12");
    const uint32_t version = readU32(&file[4]);
    const uint32_t length = readU32(&file[8]);
    if (version != 2) ctx.fail("unsupported GLB version " + std::to_string(version) + " (expected 2)");
    if (length > file.size())
        ctx.fail("truncated GLB: header says " + std::to_string(length) + " bytes, file has " +
                 std::to_string(file.size()));
    GlbChunks chunks;
    for (uint64_t offset = 12, index = 0; offset < length; ++index) {
        if (length - offset < 8) ctx.fail("truncated GLB: chunk header at byte " + std::to_string(offset));
        const uint32_t chunkLength = readU32(&file[offset]);
        const uint32_t chunkType = readU32(&file[offset + 4]);
        if (chunkLength > length - offset - 8)
            ctx.fail("corrupt GLB: chunk " + std::to_string(index) + " claims " + std::to_string(chunkLength) +
                     " bytes, only " + std::to_string(length - offset - 8) + " remain");
        const uint8_t* data = &file[offset + 8];
        if (chunkLength % 4 != 0)
            ctx.warn("GLB chunk " + std::to_string(index) + " length " + std::to_string(chunkLength) +
                     " is not a multiple of 4 (tolerated)");
        if (index == 0) {
            if (chunkType != kChunkJson) ctx.fail("corrupt GLB: the first chunk is not JSON");
            chunks.json = std::string_view(reinterpret_cast<const char*>(data), chunkLength);
        } else if (index == 1 && chunkType == kChunkBin) {
            chunks.bin = std::span<const uint8_t>(data, chunkLength);
        }  // other chunk types are ignored, as the specification asks
        offset += 8 + uint64_t(chunkLength);
    }
    if (chunks.json.empty()) ctx.fail("corrupt GLB: no JSON chunk");
    return chunks;
}

// A canonical GLB (JSON chunk, optional BIN chunk, both padded to 4 bytes) whose lengths tinygltf
// can trust.
std::vector<uint8_t> canonicalGlb(const LoadContext& ctx, std::string_view json, std::span<const uint8_t> bin) {
    const size_t jsonPadded = (json.size() + 3) & ~size_t(3);
    const size_t binPadded = (bin.size() + 3) & ~size_t(3);
    std::vector<uint8_t> out;
    out.reserve(12 + 8 + jsonPadded + 8 + binPadded);
    appendU32(out, kGlbMagic);
    appendU32(out, 2);
    appendU32(out, 0);  // total length, patched below
    appendU32(out, uint32_t(jsonPadded));
    appendU32(out, kChunkJson);
    out.insert(out.end(), json.begin(), json.end());
    out.resize(out.size() + (jsonPadded - json.size()), ' ');
    // An empty BIN chunk is dropped: tinygltf rejects BIN chunks shorter than 4 bytes.
    if (!bin.empty()) {
        appendU32(out, uint32_t(binPadded));
        appendU32(out, kChunkBin);
        out.insert(out.end(), bin.begin(), bin.end());
        out.resize(out.size() + (binPadded - bin.size()), 0);
    }
    if (out.size() >= std::numeric_limits<uint32_t>::max()) ctx.fail("GLB larger than 4 GiB");
    const uint32_t total = uint32_t(out.size());
    for (int i = 0; i < 4; ++i) out[8 + i] = uint8_t(total >> (8 * i));
    return out;
}

// File access for tinygltf: only files inside the model's folder, named by relative URIs.
struct FsState {
    std::string base;     // absolute folder of the model, ending in '/'
    std::string problem;  // first URI that could not be used, as a one-line message
    const UriReader* reader = nullptr;  // set: URIs are read by it, not from the file system
    std::map<std::string, std::vector<uint8_t>> read;  // what the reader gave, by relative URI
    void record(std::string message) {
        if (problem.empty()) problem = std::move(message);
    }
};

// Why a (percent-decoded) relative URI may not be read, if it may not.
std::optional<std::string> uriProblem(const std::string& rel) {
    if (rel.find('\0') != std::string::npos) return "contains a NUL character";
    if (rel.front() == '/' || rel.front() == '\\') return "is an absolute path";
    // RFC 3986: a relative reference's first segment has no ':', so "x:..." is a scheme (file:, http:).
    const size_t colon = rel.find(':');
    if (colon != std::string::npos && rel.find('/') > colon) return "uses an unsupported URI scheme";
    const std::filesystem::path normal = std::filesystem::path(rel).lexically_normal();
    if (normal.empty() || *normal.begin() == "..") return "escapes the model's folder";
    return std::nullopt;
}

bool fsFileExists(const std::string& absPath, void* user) {
    auto& fs = *static_cast<FsState*>(user);
    // tinygltf also tries "./URI" (the current directory): never allowed.
    if (absPath.size() <= fs.base.size() || absPath.compare(0, fs.base.size(), fs.base) != 0) return false;
    const std::string rel = absPath.substr(fs.base.size());
    if (const auto why = uriProblem(rel)) {
        fs.record("URI '" + rel + "' " + *why);
        return false;
    }
    if (fs.reader) {
        std::optional<std::vector<uint8_t>> bytes = (*fs.reader)(rel);
        if (!bytes) {
            fs.record("cannot read '" + rel + "': the URI resolver has no such file");
            return false;
        }
        fs.read[rel] = std::move(*bytes);
        return true;
    }
    std::error_code ec;
    const auto status = std::filesystem::status(absPath, ec);
    if (!std::filesystem::exists(status)) {
        fs.record("cannot read '" + rel + "': file not found");
        return false;
    }
    if (!std::filesystem::is_regular_file(status)) {
        fs.record("cannot read '" + rel + "': not a regular file");
        return false;
    }
    return true;
}

std::string fsExpandFilePath(const std::string& path, void*) { return path; }

bool fsReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& absPath, void* user) {
    auto& fs = *static_cast<FsState*>(user);
    const std::string rel = absPath.size() > fs.base.size() ? absPath.substr(fs.base.size()) : absPath;
    if (fs.reader) {
        const auto it = fs.read.find(rel);
        if (it == fs.read.end()) {
            fs.record("cannot read '" + rel + "': the URI resolver has no such file");
            return false;
        }
        if (it->second.size() >= std::numeric_limits<uint32_t>::max()) {
            fs.record("cannot read '" + rel + "': larger than 4 GiB");
            return false;
        }
        *out = std::move(it->second);
        fs.read.erase(it);
        if (out->empty()) fs.record("cannot read '" + rel + "': empty file");
        return true;
    }
    std::ifstream in(absPath, std::ios::binary);
    if (!in) {
        fs.record("cannot read '" + rel + "': " + std::strerror(errno));
        if (err) *err += "cannot open " + rel;
        return false;
    }
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0);
    if (size < 0 || size_t(size) >= std::numeric_limits<uint32_t>::max()) {
        fs.record("cannot read '" + rel + "': unreadable or larger than 4 GiB");
        return false;
    }
    out->resize(size_t(size));
    if (size > 0 && !in.read(reinterpret_cast<char*>(out->data()), size)) {
        fs.record("cannot read '" + rel + "': read error");
        return false;
    }
    if (out->empty()) fs.record("cannot read '" + rel + "': empty file");
    return true;
}

bool fsWriteWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not supported";
    return false;
}

// KHR_animation_pointer channels have no target node, and tinygltf 2.7 drops every channel without
// one: each such channel gets "node": -1 (which tinygltf keeps as target_node -1 and the schema check
// has already seen absent), so that the loader sees every channel, at its index. True if any did.
bool keepChannelsWithoutNode(nlohmann::json& doc) {
    bool changed = false;
    const auto animations = doc.find("animations");
    if (animations == doc.end() || !animations->is_array()) return false;
    for (nlohmann::json& animation : *animations) {
        const auto channels = animation.find("channels");
        if (channels == animation.end() || !channels->is_array()) continue;
        for (nlohmann::json& channel : *channels) {
            const auto target = channel.find("target");
            if (target == channel.end() || !target->is_object() || target->contains("node")) continue;
            (*target)["node"] = -1;
            changed = true;
        }
    }
    return changed;
}

struct ImageLoaderState {
    const LoadContext* ctx;
    uint32_t maxDimension;
    std::map<int, std::vector<uint8_t>>* out;
    std::exception_ptr error;
};

bool loadImageCallback(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                       const unsigned char* bytes, int size, void* user) {
    auto& state = *static_cast<ImageLoaderState*>(user);
    // bufferView images: tinygltf has not checked the view's range, so `bytes` may be out of
    // bounds. ImageTable decodes them later from a checked view.
    if (image->bufferView >= 0) return true;
    try {
        const std::span<const uint8_t> encoded(bytes, size_t(std::max(size, 0)));
        // Absurd sizes fail now. Formats stb_image cannot read (WebP or KTX2 behind optional
        // extensions) fail only if a material samples them, when ImageTable decodes.
        checkImageHeader(*state.ctx, encoded, label("image", index, image->name), state.maxDimension, true);
        (*state.out)[index].assign(encoded.begin(), encoded.end());
    } catch (...) {
        // Never let an exception unwind through tinygltf; rethrown after it returns.
        state.error = std::current_exception();
        return false;
    }
    return true;
}

// The kind of file `file` looks like when it is one of the images or environments people pass
// for a scene by mistake ("" otherwise).
std::string notGltfKind(std::span<const uint8_t> file) {
    const auto starts = [&](std::string_view magic) {
        return file.size() >= magic.size() && std::memcmp(file.data(), magic.data(), magic.size()) == 0;
    };
    if (starts("\x89PNG\r\n\x1a\n")) return "a PNG image";
    if (starts("\xff\xd8\xff")) return "a JPEG image";
    if (starts("RIFF") && file.size() >= 12 && std::memcmp(file.data() + 8, "WEBP", 4) == 0) return "a WebP image";
    if (starts("\xabKTX 20\xbb")) return "a KTX2 texture";
    if (starts("#?RADIANCE") || starts("#?RGBE")) return "a Radiance HDR environment (use it with --env)";
    if (starts("\x76\x2f\x31\x01")) return "an OpenEXR image (an environment goes to --env)";
    return "";
}

}  // namespace

ParsedFile parseGltf(const LoadContext& ctx, std::span<const uint8_t> file, const std::filesystem::path& path,
                     uint32_t maxImageDimension, const UriReader& reader) {
    if (file.empty()) ctx.fail("empty file");
    if (file.size() >= std::numeric_limits<uint32_t>::max()) ctx.fail("file larger than 4 GiB");
    if (const std::string kind = notGltfKind(file); !kind.empty()) ctx.fail("not a glTF file: looks like " + kind);
    const bool binary = file.size() >= 4 && readU32(file.data()) == kGlbMagic;
    GlbChunks chunks;
    if (binary) chunks = readGlb(ctx, file);
    std::string_view json = binary ? chunks.json : std::string_view(reinterpret_cast<const char*>(file.data()), file.size());
    if (jsonDepth(json, kMaxJsonDepth) > kMaxJsonDepth)
        ctx.fail("invalid glTF: JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    checkGltfJson(ctx, json);

    ParsedFile parsed;
    // What tinygltf would refuse in a valid file is taken out of the JSON first.
    std::string rewritten;
    if (json.find("KHR_draco_mesh_compression") != std::string_view::npos ||
        json.find("EXT_meshopt_compression") != std::string_view::npos ||
        json.find("KHR_animation_pointer") != std::string_view::npos) {
        nlohmann::json doc = nlohmann::json::parse(json.begin(), json.end());
        const bool draco = detachDracoIndices(doc, parsed.dracoIndices);
        const bool meshopt = emptyMeshoptFallbackBuffers(doc, binary);
        const bool channels = keepChannelsWithoutNode(doc);
        if (draco || meshopt || channels) {
            rewritten = doc.dump();
            json = rewritten;
        }
    }
    std::vector<uint8_t> glb;
    if (binary) glb = canonicalGlb(ctx, json, chunks.bin);
    FsState fs;
    if (reader) fs.reader = &reader;
    std::error_code ec;
    const std::filesystem::path folder = std::filesystem::absolute(path, ec).lexically_normal().parent_path();
    fs.base = folder.string();
    if (fs.base.empty() || fs.base.back() != '/') fs.base += '/';
    ImageLoaderState images{&ctx, maxImageDimension, &parsed.uriImages, nullptr};

    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&fsFileExists, &fsExpandFilePath, &fsReadWholeFile, &fsWriteWholeFile, &fs});
    loader.SetImageLoader(&loadImageCallback, &images);
    std::string err;
    std::string warn;
    const bool ok =
        binary ? loader.LoadBinaryFromMemory(&parsed.model, &err, &warn, glb.data(), unsigned(glb.size()), fs.base)
               : loader.LoadASCIIFromString(&parsed.model, &err, &warn, json.data(), unsigned(json.size()), fs.base);
    if (images.error) std::rethrow_exception(images.error);
    if (!fs.problem.empty()) ctx.fail(fs.problem);
    if (!ok) ctx.fail("invalid glTF: " + oneLine(err, fs.base));
    if (!warn.empty()) ctx.warn("tinygltf: " + oneLine(warn, fs.base));

    for (size_t i = 0; i < parsed.model.images.size(); ++i) {
        const tinygltf::Image& image = parsed.model.images[i];
        if (image.bufferView < 0 && !parsed.uriImages.count(int(i)))
            ctx.fail(label("image", int(i), image.name) + ": no image data");
    }
    return parsed;
}

}  // namespace candela::assets::gltf
