#include "assets/gltf_images.h"

#include "assets/gltf_accessors.h"
#include "assets/image_file.h"
#include "assets/stb_image_decoder.h"

#include "core/errors.h"
#include "core/parallel_for.h"
#include "core/process_memory.h"
#include "textures/ktx2_file.h"
#include "textures/webp_image.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <system_error>
#include <utility>

namespace candela::assets::gltf {
namespace {

// The size a PNG declares in its IHDR chunk. stb_image refuses (in stbi_info too) PNGs whose
// decoded size would pass 1 GiB, with a reason that names no size; this finds the size to report.
bool pngDeclaredSize(std::span<const uint8_t> bytes, uint32_t& width, uint32_t& height) {
    static const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (bytes.size() < 24 || std::memcmp(bytes.data(), kSignature, 8) != 0 || std::memcmp(&bytes[12], "IHDR", 4) != 0)
        return false;
    auto be32 = [&](size_t at) {
        return uint32_t(bytes[at]) << 24 | uint32_t(bytes[at + 1]) << 16 | uint32_t(bytes[at + 2]) << 8 | bytes[at + 3];
    };
    width = be32(16);
    height = be32(20);
    return true;
}

std::string sizeProblem(uint32_t width, uint32_t height, uint32_t maxDimension) {
    return "image size " + std::to_string(width) + "x" + std::to_string(height) + " exceeds the limit of " +
           std::to_string(maxDimension) + " pixels per side";
}

std::string stbiReason() {
    const char* reason = stb::failureReason();
    return reason ? reason : "unknown reason";
}

}  // namespace

uint64_t ImageHeader::decodedBytes() const {
    uint64_t bytes = 0;
    for (uint32_t level = 0; level < levels; ++level)
        bytes += uint64_t(std::max(1u, width >> level)) * std::max(1u, height >> level) * 4;
    return bytes;
}

namespace {

// The header of a format candela_textures reads: (width, height, levels), or a UserError.
ImageHeader texturesHeader(std::span<const uint8_t> bytes, uint32_t maxDimension) {
    if (textures::isKtx2(bytes)) {
        const textures::Ktx2Info info = textures::readKtx2Info(bytes, maxDimension);
        return {info.width, info.height, info.levelCount};
    }
    const auto [width, height] = textures::webpSize(bytes, maxDimension);
    return {width, height, 1};
}


}  // namespace

ImageHeader checkImageHeader(const LoadContext& ctx, std::span<const uint8_t> bytes, const std::string& what,
                             uint32_t maxDimension, bool unreadableOk) {
    if (bytes.empty()) ctx.fail(what + ": no image data");
    if (textures::isKtx2(bytes) || textures::isWebp(bytes)) {
        try {
            return texturesHeader(bytes, maxDimension);
        } catch (const UserError& e) {
            if (unreadableOk) return {0, 0, 1};
            ctx.fail(what + ": " + e.what());
        }
    }
    if (bytes.size() > size_t(std::numeric_limits<int>::max())) ctx.fail(what + ": image data larger than 2 GiB");
    int width = 0, height = 0, channels = 0;
    // Read only the header first: an absurd declared size must not reach the decoder's allocation.
    if (!stb::info(bytes, width, height, channels)) {
        const std::string reason = stbiReason();
        uint32_t pngWidth = 0, pngHeight = 0;
        if (pngDeclaredSize(bytes, pngWidth, pngHeight) && (pngWidth > maxDimension || pngHeight > maxDimension))
            ctx.fail(what + ": " + sizeProblem(pngWidth, pngHeight, maxDimension));
        if (unreadableOk) return {0, 0, 1};
        ctx.fail(what + ": cannot decode image (" + reason + ")");
    }
    if (width <= 0 || height <= 0 || uint32_t(width) > maxDimension || uint32_t(height) > maxDimension)
        ctx.fail(what + ": " + sizeProblem(uint32_t(std::max(width, 0)), uint32_t(std::max(height, 0)), maxDimension));
    return {uint32_t(width), uint32_t(height), 1};
}

DecodedImage decodeImage(const LoadContext& ctx, std::span<const uint8_t> bytes, const std::string& what,
                         uint32_t maxDimension) {
    const ImageHeader header = checkImageHeader(ctx, bytes, what, maxDimension);
    DecodedImage image;
    if (textures::isKtx2(bytes) || textures::isWebp(bytes)) {
        textures::DecodedTexture texture;
        try {
            texture = textures::isKtx2(bytes) ? textures::decodeKtx2(bytes, maxDimension)
                                              : textures::decodeWebp(bytes, maxDimension);
        } catch (const UserError& e) {
            ctx.fail(what + ": " + e.what());
        }
        for (const std::string& note : texture.report.notes) image.notes.push_back(what + ": " + note);
        for (const std::string& warning : texture.report.warnings) image.warnings.push_back(what + ": " + warning);
        if (textures::isKtx2(bytes)) {
            const textures::Ktx2Info info = textures::readKtx2Info(bytes, maxDimension);
            image.fileSrgb = info.srgb;
            image.format = info.payload == textures::BasisPayload::Etc1s ? "KTX2 ETC1S"
                           : info.supercompression == textures::Supercompression::Zstandard ? "KTX2 UASTC+zstd"
                                                                                            : "KTX2 UASTC";
        } else {
            image.format = "WebP";
        }
        image.width = texture.levels[0].width;
        image.height = texture.levels[0].height;
        image.rgba8 = std::move(texture.levels[0].rgba8);
        for (size_t level = 1; level < texture.levels.size(); ++level) image.mips.push_back(std::move(texture.levels[level].rgba8));
        return image;
    }
    const uint32_t width = header.width, height = header.height;
    image.format = pngDeclaredSize(bytes, image.width, image.height) ? "PNG"
                   : bytes.size() >= 2 && bytes[0] == 0xFF && bytes[1] == 0xD8 ? "JPEG"
                                                                               : "other";
    if (image.format == "PNG")
        if (const std::string problem = assets::pngChunkProblem(bytes); !problem.empty()) ctx.fail(what + ": " + problem);
    int w = 0, h = 0;
    const size_t texels = size_t(width) * size_t(height);
    if (stb::is16Bit(bytes)) {
        const stb::Pixels<uint16_t> pixels = stb::loadRgba16(bytes, w, h);
        if (!pixels) ctx.fail(what + ": cannot decode image (" + stbiReason() + ")");
        if (uint32_t(w) != width || uint32_t(h) != height) ctx.fail(what + ": image size changed while decoding");
        // Round to nearest (stb_image's own 16→8 path truncates).
        image.rgba8.resize(texels * 4);
        for (size_t i = 0; i < texels * 4; ++i) image.rgba8[i] = uint8_t((uint32_t(pixels.get()[i]) * 255u + 32767u) / 65535u);
    } else {
        // Decoded in place (stb::loadRgba8Into), in huge pages: a 2048² image is 4,096 fresh 4 KiB
        // pages otherwise.
        image.rgba8.reserve(texels * 4 + 1);
        adviseHugePages(image.rgba8.data(), image.rgba8.capacity());
        image.rgba8.resize(texels * 4);
        if (!stb::loadRgba8Into(bytes, w, h, image.rgba8)) ctx.fail(what + ": cannot decode image (" + stbiReason() + ")");
        if (uint32_t(w) != width || uint32_t(h) != height) ctx.fail(what + ": image size changed while decoding");
    }
    image.width = width;
    image.height = height;
    return image;
}

int textureImage(const tinygltf::Texture& texture) {
    for (const char* name : {"KHR_texture_basisu", "EXT_texture_webp"}) {
        const auto it = texture.extensions.find(name);
        if (it == texture.extensions.end() || !it->second.IsObject() || !it->second.Has("source")) continue;
        const tinygltf::Value& source = it->second.Get("source");
        if (source.IsInt() && source.GetNumberAsInt() >= 0) return source.GetNumberAsInt();
    }
    return texture.source;
}

ImageTable::ImageTable(const LoadContext& ctx, const tinygltf::Model& model,
                       std::map<int, std::vector<uint8_t>> uriImages, const LoadOptions& options, scene::Scene& scene)
    : mCtx(ctx), mModel(model), mEncoded(std::move(uriImages)), mOptions(options), mScene(scene) {}

std::span<const uint8_t> ImageTable::encoded(int index, const std::string& what) {
    // URI images were read while parsing; the rest must come from a bufferView.
    if (auto it = mEncoded.find(index); it != mEncoded.end()) return it->second;
    const tinygltf::Image& image = mModel.images[size_t(index)];
    if (image.bufferView < 0) mCtx.fail(what + ": no image data");
    return bufferViewBytes(mCtx, mModel, image.bufferView, what);
}

uint64_t ImageTable::declaredBytes(int index) {
    const std::string what = label("image", index, mModel.images[size_t(index)].name);
    const ImageHeader header = checkImageHeader(mCtx, encoded(index, what), what, mOptions.maxImageDimension);
    const uint64_t bytes = header.decodedBytes();
    if (bytes > mOptions.maxImageBytes)
        mCtx.fail(what + ": " + std::to_string(header.width) + "x" + std::to_string(header.height) +
                  (header.levels > 1 ? " with " + std::to_string(header.levels) + " levels" : std::string()) + " decodes to " +
                  formatBytes(bytes) + " of RGBA8, above the limit of " + formatBytes(mOptions.maxImageBytes) + " per image");
    return bytes;
}

void ImageTable::checkDecodedSize(const std::set<std::pair<int, bool>>& uses) {
    uint64_t total = 0;
    for (const auto& [image, srgb] : uses) {
        if (image < 0 || size_t(image) >= mModel.images.size()) continue;
        total += declaredBytes(image);
    }
    if (total > mOptions.maxTotalImageBytes)
        mCtx.fail("decoded images would take " + formatBytes(total) + ", above the limit of " +
                  formatBytes(mOptions.maxTotalImageBytes) + " per scene");
}

DecodedImage& ImageTable::keep(int index, DecodedImage image, uint64_t declaredBytes) {
    for (const std::string& note : image.notes) mCtx.note(note);
    for (const std::string& warning : image.warnings) mCtx.warn(warning);
    scene::SceneLoadReport::TextureDecoding& stats = mScene.report.textureDecoding;
    ++stats.formats[image.format];
    stats.encodedBytes += image.encodedBytes;
    stats.decodedBytes += declaredBytes;
    mEncoded.erase(index);
    return mDecoded[index] = std::move(image);
}

DecodedImage& ImageTable::decoded(int index) {
    auto it = mDecoded.find(index);
    if (it != mDecoded.end()) return it->second;
    const std::string what = label("image", index, mModel.images[size_t(index)].name);
    const uint64_t decodedBytes = declaredBytes(index);  // the per-image limit, before any pixel is decoded
    const auto start = std::chrono::steady_clock::now();
    const std::span<const uint8_t> bytes = encoded(index, what);
    DecodedImage image = decodeImage(mCtx, bytes, what, mOptions.maxImageDimension);
    image.encodedBytes = bytes.size();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    mScene.report.textureDecoding.milliseconds += ms;
    mScene.report.textureDecoding.waitMilliseconds += ms;  // on the loading thread
    return keep(index, std::move(image), decodedBytes);
}

namespace {

// An image's pixels and what describes them, from its decode (moved: its first entry) or from its
// entry of the other encoding (copied).
template <typename From>
void setPixels(From&& from, scene::Image& to) {
    to.width = from.width;
    to.height = from.height;
    to.format = from.format;
    to.encodedBytes = from.encodedBytes;
    to.rgba8 = std::forward<From>(from).rgba8;
    to.mips = std::forward<From>(from).mips;
}

}  // namespace

ImageTable::~ImageTable() {
    if (mDecode && mDecode->thread.joinable()) mDecode->thread.join();
}

void ImageTable::run(Decode& decode, const LoadContext& ctx, uint32_t maxDimension) {
    const auto start = std::chrono::steady_clock::now();
    try {
        std::vector<size_t> order(decode.jobs.size());
        for (size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(),
                         [&](size_t a, size_t b) { return decode.jobs[a].bytes.size() > decode.jobs[b].bytes.size(); });
        parallelFor(order.size(), [&](size_t k) {
            const Job& job = decode.jobs[order[k]];
            try {
                decode.images[order[k]] = decodeImage(ctx, job.bytes, job.what, maxDimension);
                decode.images[order[k]].encodedBytes = job.bytes.size();
            } catch (...) {
                decode.errors[order[k]] = std::current_exception();
            }
        });
    } catch (...) {
        decode.failure = std::current_exception();
    }
    decode.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

const ImageTable::Job* ImageTable::pendingJob(int index) const {
    if (!mDecode) return nullptr;
    for (const Job& job : mDecode->jobs)
        if (job.index == index) return &job;
    return nullptr;
}

void ImageTable::decodeAll(const std::set<std::pair<int, bool>>& uses) {
    finishDecodes();  // one decode at a time
    // Each image once; their encoded bytes and declared sizes found here (bufferViews range-checked,
    // limits applied) before any decoding starts.
    auto decode = std::make_unique<Decode>();
    for (const auto& [index, srgb] : uses) {
        if (index < 0 || size_t(index) >= mModel.images.size() || mDecoded.count(index) ||
            (!decode->jobs.empty() && decode->jobs.back().index == index))
            continue;
        const std::string what = label("image", index, mModel.images[size_t(index)].name);
        decode->jobs.push_back({index, what, encoded(index, what), declaredBytes(index)});
    }
    if (decode->jobs.empty()) return;
    decode->images.resize(decode->jobs.size());
    decode->errors.resize(decode->jobs.size());
    decode->warningsAt = mCtx.warnings->size();
    decode->notesAt = mCtx.notes ? mCtx.notes->size() : 0;
    const bool background = mOptions.decodeBesideTheLoad && std::none_of(decode->jobs.begin(), decode->jobs.end(),
                                                         [](const Job& job) { return textures::isKtx2(job.bytes); });
    mDecode = std::move(decode);
    if (background) {
        try {
            mDecode->thread = std::thread([decode = mDecode.get(), ctx = &mCtx, maxDimension = mOptions.maxImageDimension] {
                run(*decode, *ctx, maxDimension);
            });
            return;
        } catch (const std::system_error&) {
            // No thread to be had: decoded here.
        }
    }
    run(*mDecode, mCtx, mOptions.maxImageDimension);
    finishDecodes();
}

void ImageTable::finishDecodes() {
    if (!mDecode) return;
    const std::unique_ptr<Decode> decode = std::move(mDecode);
    scene::SceneLoadReport::TextureDecoding& report = mScene.report.textureDecoding;
    if (decode->thread.joinable()) {
        const auto start = std::chrono::steady_clock::now();
        decode->thread.join();
        report.waitMilliseconds += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    } else {
        report.waitMilliseconds += decode->milliseconds;
    }
    report.milliseconds += decode->milliseconds;
    if (decode->failure) std::rethrow_exception(decode->failure);
    // The lines recorded while it ran go after its own, as if it had ended where it began.
    const LoadContext::Lines later = mCtx.takeSince(decode->warningsAt, decode->notesAt);
    for (size_t j = 0; j < decode->jobs.size(); ++j) {
        if (decode->errors[j]) std::rethrow_exception(decode->errors[j]);
        keep(decode->jobs[j].index, std::move(decode->images[j]), decode->jobs[j].declaredBytes);
    }
    mCtx.restore(later);
    // The entries resolve() made meanwhile: the first of an image takes its pixels, a second use
    // (the other encoding) copies them.
    std::map<int, int> first;  // glTF image → its first entry
    for (const auto& [entry, index] : decode->entries) {
        scene::Image& image = mScene.images[size_t(entry)];
        if (const auto it = first.find(index); it != first.end()) {
            setPixels(mScene.images[size_t(it->second)], image);
        } else {
            first[index] = entry;
            setPixels(std::move(mDecoded.at(index)), image);
        }
    }
}

int ImageTable::resolve(int index, bool srgb) {
    if (auto it = mEntries.find({index, srgb}); it != mEntries.end()) return it->second;
    const tinygltf::Image& source = mModel.images[size_t(index)];
    scene::Image image;
    image.name = !source.name.empty() ? source.name
                 : (!source.uri.empty() && source.uri.rfind("data:", 0) != 0) ? source.uri
                                                                               : "image " + std::to_string(index);
    image.srgb = srgb;
    // The pixels move into the first entry; a second use (other encoding) copies from there. An
    // image still decoding gets them when finishDecodes takes it in.
    if (pendingJob(index)) {
        mDecode->entries.emplace_back(int(mScene.images.size()), index);
    } else if (auto other = mEntries.find({index, !srgb}); other != mEntries.end()) {
        setPixels(mScene.images[size_t(other->second)], image);
    } else {
        setPixels(std::move(decoded(index)), image);
    }
    if (const auto it = mDecoded.find(index); it != mDecoded.end() && it->second.fileSrgb && *it->second.fileSrgb != srgb)
        mCtx.warn(label("image", index, source.name) + ": the KTX2 file's transfer function is " +
                  (*it->second.fileSrgb ? "sRGB" : "linear") + " but a material reads it as " + (srgb ? "colour (sRGB)" : "linear data") +
                  " (KHR_texture_basisu requires them to match; read as the material asks)");
    const int entry = int(mScene.images.size());
    mScene.images.push_back(std::move(image));
    mEntries[{index, srgb}] = entry;
    return entry;
}

}  // namespace candela::assets::gltf
