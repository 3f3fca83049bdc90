#include "ibl/ibl_cache_file.h"

#include "core/cache_fields.h"
#include "core/cache_files.h"
#include "core/errors.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace candela::ibl {
namespace {

namespace fs = std::filesystem;

constexpr std::array<char, 12> kMagic = {'C', 'A', 'N', 'D', 'E', 'L', 'A', '-', 'I', 'B', 'L', '\0'};

// `text` made printable on one line (control bytes become '?') and cut to `limit` characters.
std::string printable(std::string_view text, size_t limit = 80) {
    std::string out;
    for (char c : text.substr(0, limit)) out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
    if (text.size() > limit) out += "...";
    return out;
}

// a * b and a + b, or nullopt on uint64_t overflow.
std::optional<uint64_t> mulChecked(uint64_t a, uint64_t b) {
    if (a != 0 && b > std::numeric_limits<uint64_t>::max() / a) return std::nullopt;
    return a * b;
}
std::optional<uint64_t> addChecked(uint64_t a, uint64_t b) {
    if (b > std::numeric_limits<uint64_t>::max() - a) return std::nullopt;
    return a + b;
}

uint32_t mipLevelsOfFullChain(uint32_t width, uint32_t height) {
    uint32_t levels = 1;
    for (uint32_t extent = std::max(width, height); extent > 1; extent >>= 1) ++levels;
    return levels;
}

// The first violated limit among the image's dimensions (not its name or data), or "".
std::string dimensionProblem(const CachedImage& image) {
    const std::string prefix = "image '" + printable(image.name) + "': ";
    auto range = [&](const char* field, uint32_t value, uint32_t max) {
        return prefix + field + " " + std::to_string(value) + " is not in 1.." + std::to_string(max);
    };
    if (image.texelBytes < 1 || image.texelBytes > kIblCacheMaxTexelBytes) return range("texelBytes", image.texelBytes, kIblCacheMaxTexelBytes);
    if (image.width < 1 || image.width > kIblCacheMaxExtent) return range("width", image.width, kIblCacheMaxExtent);
    if (image.height < 1 || image.height > kIblCacheMaxExtent) return range("height", image.height, kIblCacheMaxExtent);
    if (image.layers < 1 || image.layers > kIblCacheMaxLayers) return range("layers", image.layers, kIblCacheMaxLayers);
    if (image.mips < 1 || image.mips > kIblCacheMaxMips) return range("mips", image.mips, kIblCacheMaxMips);
    if (const uint32_t full = mipLevelsOfFullChain(image.width, image.height); image.mips > full)
        return prefix + "mips " + std::to_string(image.mips) + " exceeds the " + std::to_string(full) + " levels of a " +
               std::to_string(image.width) + "x" + std::to_string(image.height) + " image";
    return {};
}

std::string nameProblem(size_t nameLength) {
    if (nameLength < 1 || nameLength > kIblCacheMaxNameLength)
        return "image name length " + std::to_string(nameLength) + " is not in 1.." + std::to_string(kIblCacheMaxNameLength);
    return {};
}

std::string dataSizeProblem(const CachedImage& image, uint64_t dataBytes) {
    const size_t expected = image.expectedBytes();
    if (dataBytes == expected) return {};
    return "image '" + printable(image.name) + "': " + std::to_string(dataBytes) + " data bytes, but " +
           std::to_string(image.width) + "x" + std::to_string(image.height) + ", " + std::to_string(image.layers) +
           " layers, " + std::to_string(image.mips) + " mips of " + std::to_string(image.texelBytes) + "-byte texels make " +
           std::to_string(expected);
}

// Writes what a CacheFieldWriter writes to a stream.
struct StreamSink {
    std::ostream* out;
    void operator()(const void* data, size_t size) const { out->write(static_cast<const char*>(data), std::streamsize(size)); }
};

// Reads a CacheFieldReader's bytes from a file stream.
struct StreamSource {
    std::ifstream* in;
    bool operator()(void* out, size_t size) const {
        in->read(static_cast<char*>(out), std::streamsize(size));
        return *in && size_t(in->gcount()) == size;
    }
};

using Reader = CacheFieldReader<StreamSource>;

// Reads the fields of one image, checking each size before allocating for it.
bool readImage(Reader& in, uint32_t index, uint64_t& payload, CachedImage& image) {
    const std::string what = "image " + std::to_string(index);
    uint32_t nameLength = 0;
    if (!in.u32(nameLength, what + "'s name length")) return false;
    if (std::string p = nameProblem(nameLength); !p.empty()) return in.fail(what + ": " + p);
    std::array<char, kIblCacheMaxNameLength> name{};
    if (!in.bytes(name.data(), nameLength, what + "'s name")) return false;
    image.name.assign(name.data(), nameLength);

    const std::string named = "image '" + printable(image.name) + "'";
    const std::array<std::pair<uint32_t*, const char*>, 6> fields = {{{&image.format, "format"},
                                                                      {&image.texelBytes, "texelBytes"},
                                                                      {&image.width, "width"},
                                                                      {&image.height, "height"},
                                                                      {&image.layers, "layers"},
                                                                      {&image.mips, "mips"}}};
    for (const auto& [field, label] : fields)
        if (!in.u32(*field, named + "'s " + label)) return false;
    if (std::string p = dimensionProblem(image); !p.empty()) return in.fail(p);

    uint64_t dataBytes = 0;
    if (!in.u64(dataBytes, named + "'s data size")) return false;
    if (std::string p = dataSizeProblem(image, dataBytes); !p.empty()) return in.fail(p);
    payload += dataBytes;  // no overflow: each image is below 2^40 bytes within the limits, at most 16 images
    if (payload > kIblCacheMaxPayloadBytes)
        return in.fail("the images' data adds up to more than " + std::to_string(kIblCacheMaxPayloadBytes) + " bytes");
    const uint64_t available = in.remaining() > 8 ? in.remaining() - 8 : 0;  // the checksum follows
    if (dataBytes > available)
        return in.fail("truncated: " + named + " declares " + std::to_string(dataBytes) + " data bytes but only " +
                       std::to_string(available) + " remain before the checksum");
    image.data.resize(size_t(dataBytes));
    return in.bytes(image.data.data(), dataBytes, named + "'s data");
}

}  // namespace

size_t CachedImage::expectedBytes() const {
    constexpr size_t kOverflow = std::numeric_limits<size_t>::max();
    const uint64_t layerTexelBytes = uint64_t(layers) * texelBytes;  // < 2^64
    uint64_t total = 0;
    for (uint32_t m = 0; m < std::min(mips, 32u); ++m) {
        const uint64_t texels = uint64_t(std::max(1u, width >> m)) * std::max(1u, height >> m);  // < 2^64
        const auto bytes = mulChecked(texels, layerTexelBytes);
        const auto sum = bytes ? addChecked(total, *bytes) : std::nullopt;
        if (!sum) return kOverflow;
        total = *sum;
    }
    if (mips > 32) {  // the rest are 1×1
        const auto bytes = mulChecked(mips - 32u, layerTexelBytes);
        const auto sum = bytes ? addChecked(total, *bytes) : std::nullopt;
        if (!sum) return kOverflow;
        total = *sum;
    }
    return total >= kOverflow ? kOverflow : size_t(total);
}

std::filesystem::path cacheFilePath(const std::filesystem::path& dir, const IblCacheKey& key) {
    return dir / (hex16(key.environmentHash) + "-" + hex16(fnv1a64(key.settings)) + ".cibl");
}

void writeCacheFile(const std::filesystem::path& path, const IblCacheKey& key, const std::vector<CachedImage>& images) {
    const std::string name = path.string();
    auto invalid = [&](const std::string& problem) { throw std::invalid_argument(name + ": " + problem); };
    if (images.size() > kIblCacheMaxImages)
        invalid(std::to_string(images.size()) + " images, more than " + std::to_string(kIblCacheMaxImages));
    if (key.settings.size() > std::numeric_limits<uint32_t>::max()) invalid("settings text longer than 4 GiB");
    uint64_t payload = 0;
    for (const CachedImage& image : images) {
        if (std::string p = nameProblem(image.name.size()); !p.empty()) invalid(p);
        if (std::string p = dimensionProblem(image); !p.empty()) invalid(p);
        if (std::string p = dataSizeProblem(image, image.data.size()); !p.empty()) invalid(p);
        payload += image.data.size();
    }
    if (payload > kIblCacheMaxPayloadBytes)
        invalid("the images' data adds up to more than " + std::to_string(kIblCacheMaxPayloadBytes) + " bytes");

    writeFileAtomically(path, [&](std::ostream& out) {
        CacheFieldWriter writer(StreamSink{&out});
        writer.bytes(kMagic.data(), kMagic.size());
        writer.u32(kIblCacheVersion);
        writer.u64(key.environmentHash);
        writer.u32(uint32_t(key.settings.size()));
        writer.bytes(key.settings.data(), key.settings.size());
        writer.u32(uint32_t(images.size()));
        for (const CachedImage& image : images) {
            writer.u32(uint32_t(image.name.size()));
            writer.bytes(image.name.data(), image.name.size());
            for (uint32_t v : {image.format, image.texelBytes, image.width, image.height, image.layers, image.mips}) writer.u32(v);
            writer.u64(image.data.size());
            writer.bytes(image.data.data(), image.data.size());
        }
        writer.u64(writer.hash());
    });
}

std::optional<std::vector<CachedImage>> readCacheFile(const std::filesystem::path& path, const IblCacheKey& key,
                                                      std::string* reason) {
    auto miss = [&](const std::string& problem) -> std::optional<std::vector<CachedImage>> {
        if (reason) *reason = path.string() + ": " + problem;
        return std::nullopt;
    };
    std::error_code ec;
    if (fs::is_directory(path, ec)) return miss("is a directory");
    std::ifstream file(path, std::ios::binary);
    if (!file) return miss(std::string("cannot open: ") + std::strerror(errno));
    file.seekg(0, std::ios::end);
    const std::streamoff size = file.tellg();
    file.seekg(0, std::ios::beg);
    if (size < 0 || !file) return miss("cannot read the file size");
    if (size == 0) return miss("empty file");

    Reader in(uint64_t(size), StreamSource{&file});
    std::array<char, kMagic.size()> magic{};
    if (!in.bytes(magic.data(), magic.size(), "the magic")) return miss(in.problem());
    if (magic != kMagic) return miss("not an IBL cache file (bad magic)");
    uint32_t version = 0;
    if (!in.u32(version, "the version")) return miss(in.problem());
    if (version != kIblCacheVersion)
        return miss("cache format version " + std::to_string(version) + ", expected " + std::to_string(kIblCacheVersion));

    uint64_t environmentHash = 0;
    if (!in.u64(environmentHash, "the environment hash")) return miss(in.problem());
    if (environmentHash != key.environmentHash)
        return miss("made for another environment (content hash " + hex16(environmentHash) + ", expected " +
                    hex16(key.environmentHash) + ")");
    uint32_t settingsLength = 0;
    if (!in.u32(settingsLength, "the settings length")) return miss(in.problem());
    if (settingsLength > in.remaining())  // before allocating for it
        return miss("truncated: the settings text of " + std::to_string(settingsLength) + " bytes passes the end of the file");
    std::string settings(settingsLength, '\0');
    if (!in.bytes(settings.data(), settingsLength, "the settings text")) return miss(in.problem());
    if (settings != key.settings)
        return miss("made for other settings ('" + printable(settings) + "', expected '" + printable(key.settings) + "')");

    uint32_t count = 0;
    if (!in.u32(count, "the image count")) return miss(in.problem());
    if (count > kIblCacheMaxImages)
        return miss(std::to_string(count) + " images, more than " + std::to_string(kIblCacheMaxImages));
    std::vector<CachedImage> images(count);
    uint64_t payload = 0;
    for (uint32_t i = 0; i < count; ++i)
        if (!readImage(in, i, payload, images[i])) return miss(in.problem());

    const uint64_t contentHash = in.hash();
    uint64_t checksum = 0;
    if (!in.u64(checksum, "the checksum")) return miss(in.problem());
    if (in.remaining() != 0) return miss(std::to_string(in.remaining()) + " unexpected bytes after the checksum");
    if (checksum != contentHash)
        return miss("checksum mismatch (stored " + hex16(checksum) + ", contents hash to " + hex16(contentHash) + "): corrupt file");
    return images;
}

}  // namespace candela::ibl
