#pragma once
// Internal to the glTF loader: image decoding (PNG and JPEG through stb_image, WebP through libwebp,
// KTX2/Basis Universal through candela_textures, all to RGBA8) and the table that maps (glTF image,
// sRGB or linear use) to Scene::images entries.

#include "assets/gltf_context.h"
#include "assets/gltf_loader.h"
#include "scene/scene.h"

#include <cstdint>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace tinygltf {
class Model;
struct Texture;
}

namespace candela::assets::gltf {

struct DecodedImage {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba8;              // width × height × 4, top row first
    std::vector<std::vector<uint8_t>> mips;  // the file's own levels 1… (KTX2), as Scene::Image::mips
    std::optional<bool> fileSrgb;            // the transfer function a KTX2 file declares
    std::string format;                      // as SceneLoadReport::TextureDecoding::formats names it
    uint64_t encodedBytes = 0;               // of the file (or buffer view) it was decoded from
    // The decoder's notes and warnings, each naming the image: for the load's log, in image order
    // (images decode in parallel; the log is written on the loading thread).
    std::vector<std::string> notes, warnings;
};

// What an image's header declares, read without decoding a pixel.
struct ImageHeader {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t levels = 1;  // levels the file stores (KTX2), else 1
    uint64_t decodedBytes() const;  // RGBA8 bytes of every stored level
};

// Reads the declared size of a PNG, JPEG (or any format stb_image reads), WebP or KTX2 image and
// rejects a width or height above `maxDimension`. A header that cannot be read fails too, unless
// `unreadableOk` (then a zero-sized header is returned). Throws via ctx.fail("WHAT: problem").
ImageHeader checkImageHeader(const LoadContext& ctx, std::span<const uint8_t> bytes, const std::string& what,
                             uint32_t maxDimension, bool unreadableOk = false);

// Decodes `bytes` to RGBA8 after checkImageHeader, so an absurd declared size allocates nothing.
// 16-bit sources are rounded to 8 bits; a KTX2 file's own mip levels are kept. The decoders' notes
// and warnings are returned in the image's, prefixed with `what`. Throws via ctx.fail("WHAT:
// problem"). Safe to call on several threads at once.
DecodedImage decodeImage(const LoadContext& ctx, std::span<const uint8_t> bytes, const std::string& what,
                         uint32_t maxDimension);

// The glTF image a texture samples: KHR_texture_basisu's source, else EXT_texture_webp's, else the
// core `source` (-1 when none is given). The extensions are alternatives to the core source
// (docs/scenes.md says why KTX2 comes first); an index that is not a non-negative integer reads as absent.
int textureImage(const tinygltf::Texture& texture);

// Creates Scene::images entries on demand, decoding only the images materials use. An image used
// both as sRGB (base colour, emissive) and as linear data becomes two entries. `uriImages` holds
// the encoded bytes of images given by URI (glTF image index → file contents). Borrows ctx, model,
// options and scene for its lifetime.
class ImageTable {
public:
    ImageTable(const LoadContext& ctx, const tinygltf::Model& model, std::map<int, std::vector<uint8_t>> uriImages,
               const LoadOptions& options, scene::Scene& scene);
    // Waits for a decode decodeAll left running (its result dropped: the load failed).
    ~ImageTable();
    ImageTable(const ImageTable&) = delete;
    ImageTable& operator=(const ImageTable&) = delete;

    // Fails, before anything is decoded, when the entries `uses` ((glTF image, srgb) pairs) would
    // exceed the options' per-image or per-scene decoded size. Indices out of range are skipped
    // (resolve's callers report them).
    void checkDecodedSize(const std::set<std::pair<int, bool>>& uses);

    // Decodes every image of `uses` ((glTF image, srgb) pairs; indices out of range skipped) at
    // once, on every core (parallelFor, the largest files first), for resolve to take; their notes
    // and warnings go to the log in image order, and the first failure in image order is thrown.
    // The report's decode time is the decode's wall time. With LoadOptions::decodeBesideTheLoad
    // (unless an image is KTX2, whose transfer function resolve() compares), the decode runs on a
    // thread of its own while the caller goes on: resolve() makes the images' entries at once and
    // finishDecodes() gives them their pixels. Otherwise it returns when done.
    void decodeAll(const std::set<std::pair<int, bool>>& uses);

    // Waits for the decode decodeAll left running and takes its images in as if it had ended
    // where decodeAll was called: their notes and warnings go before every line recorded since
    // (dropping a later copy of one, as LoadContext keeps a line once), the first failure in image
    // order is thrown, and the entries resolve() made meanwhile get their pixels. The report's
    // textureDecoding.waitMilliseconds adds the wait. Nothing when none is running.
    void finishDecodes();

    // The Scene::images index for glTF image `image` used with the given encoding; decodes it on first
    // use unless decodeAll did (bufferView images are range-checked here). Precondition: 0 <= image
    // < model.images.size().
    int resolve(int image, bool srgb);

private:
    // One image a decodeAll decodes.
    struct Job {
        int index;
        std::string what;
        std::span<const uint8_t> bytes;
        uint64_t declaredBytes;
    };
    // A decode decodeAll started: its jobs in image order, their results, and what resolve()
    // made of them meanwhile.
    struct Decode {
        std::vector<Job> jobs;
        std::vector<DecodedImage> images;
        std::vector<std::exception_ptr> errors;
        std::exception_ptr failure;                // of the decode itself (no thread, no memory)
        double milliseconds = 0.0;                 // its wall time
        size_t warningsAt = 0, notesAt = 0;        // where its lines go
        std::vector<std::pair<int, int>> entries;  // (Scene::images index, glTF image) awaiting pixels
        std::thread thread;                        // joinable while it runs in the background
    };
    // Runs `decode`'s jobs on every core, the largest files first; throws nothing (what fails is
    // kept in `decode`).
    static void run(Decode& decode, const LoadContext& ctx, uint32_t maxDimension);
    // The job of glTF image `image` in the decode running, or null.
    const Job* pendingJob(int image) const;

    DecodedImage& decoded(int image);
    // Takes a decoded image into the table: its notes and warnings to the log, its sizes to the report.
    DecodedImage& keep(int image, DecodedImage decoded, uint64_t declaredBytes);
    // The encoded bytes of glTF image `image` (bufferView images are range-checked here).
    std::span<const uint8_t> encoded(int image, const std::string& what);
    // The RGBA8 bytes the image's header declares; fails above the per-image limit.
    uint64_t declaredBytes(int image);

    const LoadContext& mCtx;
    const tinygltf::Model& mModel;
    std::map<int, std::vector<uint8_t>> mEncoded;
    std::map<int, DecodedImage> mDecoded;
    const LoadOptions& mOptions;
    scene::Scene& mScene;
    std::map<std::pair<int, bool>, int> mEntries;  // (glTF image, srgb) → Scene::images index
    std::unique_ptr<Decode> mDecode;                // a decode not yet taken in (finishDecodes)
};

}  // namespace candela::assets::gltf
