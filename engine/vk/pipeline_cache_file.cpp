#include "vk/pipeline_cache_file.h"

#include "core/cache_files.h"
#include "core/errors.h"
#include "core/log.h"
#include "vk/check.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>

namespace candela::vk {
namespace {

namespace fs = std::filesystem;

constexpr std::array<char, 12> kMagic = {'C', 'A', 'N', 'D', 'E', 'L', 'A', '-', 'P', 'S', 'O', '\0'};
constexpr size_t kDriverHeaderBytes = 32;  // VkPipelineCacheHeaderVersionOne: 4 × u32 + the UUID

std::string hex8(uint32_t v) { return hex16(v).substr(8); }

std::string hexBytes(std::span<const uint8_t> bytes) {
    std::string out;
    for (uint8_t b : bytes) out += hex16(b).substr(14);
    return out;
}

// Little-endian fields from a span; a read past the end leaves `ok` false and reads zeros.
struct Reader {
    std::span<const std::byte> bytes;
    size_t offset = 0;
    bool ok = true;
    std::span<const std::byte> take(size_t n) {
        if (!ok || n > bytes.size() - offset) {
            ok = false;
            return {};
        }
        const auto out = bytes.subspan(offset, n);
        offset += n;
        return out;
    }
    uint64_t le(size_t n) {
        uint64_t v = 0;
        const auto b = take(n);
        for (size_t i = 0; i < b.size(); ++i) v |= uint64_t(std::to_integer<uint8_t>(b[i])) << (8 * i);
        return v;
    }
    uint32_t u32() { return uint32_t(le(4)); }
    uint64_t u64() { return le(8); }
    std::array<uint8_t, VK_UUID_SIZE> uuid() {
        std::array<uint8_t, VK_UUID_SIZE> out{};
        const auto b = take(VK_UUID_SIZE);
        for (size_t i = 0; i < b.size(); ++i) out[i] = std::to_integer<uint8_t>(b[i]);
        return out;
    }
};

void putLe(std::vector<std::byte>& out, uint64_t v, size_t n) {
    for (size_t i = 0; i < n; ++i) out.push_back(std::byte(uint8_t(v >> (8 * i))));
}

// Which of the identity's parts differ, e.g. "made for another device (vendor 10de, device 2684)".
std::string identityProblem(const PipelineCacheIdentity& found, const PipelineCacheIdentity& expected, bool driverVersion) {
    if (found.vendorID != expected.vendorID || found.deviceID != expected.deviceID)
        return "made for another device (vendor " + hex8(found.vendorID) + ", device " + hex8(found.deviceID) +
               "; this one is vendor " + hex8(expected.vendorID) + ", device " + hex8(expected.deviceID) + ")";
    if (driverVersion && found.driverVersion != expected.driverVersion)
        return "made by another driver version (" + hex8(found.driverVersion) + ", this one " + hex8(expected.driverVersion) + ")";
    if (found.cacheUUID != expected.cacheUUID)
        return "made for another pipeline cache UUID (" + hexBytes(found.cacheUUID) + ", this device " +
               hexBytes(expected.cacheUUID) + ")";
    return {};
}

// The file's bytes, or nullopt and why not in *problem. Refuses files larger than any valid one.
std::optional<std::vector<std::byte>> readFile(const fs::path& path, std::string* problem) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return std::nullopt;  // no problem: none yet
    if (fs::is_directory(path, ec)) {
        *problem = "is a directory";
        return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        *problem = std::string("cannot open: ") + std::strerror(errno);
        return std::nullopt;
    }
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0, std::ios::beg);
    if (size < 0 || !in) {
        *problem = "cannot read the file size";
        return std::nullopt;
    }
    if (uint64_t(size) > kPipelineCacheFileHeaderBytes + kPipelineCacheMaxDataBytes) {
        *problem = std::to_string(size) + " bytes, more than a pipeline cache file may hold";
        return std::nullopt;
    }
    std::vector<std::byte> bytes(static_cast<size_t>(size));
    in.read(reinterpret_cast<char*>(bytes.data()), size);
    if (in.gcount() != size) {
        *problem = std::string("read failed: ") + std::strerror(errno);
        return std::nullopt;
    }
    return bytes;
}

}  // namespace

PipelineCacheIdentity PipelineCacheIdentity::of(const VkPhysicalDeviceProperties& p) {
    PipelineCacheIdentity out{.vendorID = p.vendorID, .deviceID = p.deviceID, .driverVersion = p.driverVersion};
    std::memcpy(out.cacheUUID.data(), p.pipelineCacheUUID, VK_UUID_SIZE);
    return out;
}

std::string pipelineCacheFileName(const PipelineCacheIdentity& id) {
    return "pipelines-" + hex8(id.vendorID) + "-" + hex8(id.deviceID) + "-" + hex8(id.driverVersion) + "-" +
           hexBytes(id.cacheUUID) + ".bin";
}

std::string pipelineCacheDataProblem(std::span<const std::byte> data, const PipelineCacheIdentity& identity) {
    Reader in{data};
    const uint32_t headerSize = in.u32(), headerVersion = in.u32();
    PipelineCacheIdentity found{.vendorID = in.u32(), .deviceID = in.u32()};
    found.cacheUUID = in.uuid();
    if (!in.ok) return "the driver's data is " + std::to_string(data.size()) + " bytes, shorter than its 32-byte header";
    if (headerSize < kDriverHeaderBytes || headerSize > data.size())
        return "the driver's header declares " + std::to_string(headerSize) + " bytes (32 to " + std::to_string(data.size()) +
               " expected)";
    if (headerVersion != VK_PIPELINE_CACHE_HEADER_VERSION_ONE)
        return "the driver's header has version " + std::to_string(headerVersion) + ", not VK_PIPELINE_CACHE_HEADER_VERSION_ONE";
    const std::string problem = identityProblem(found, identity, false);
    return problem.empty() ? problem : "the driver's header: " + problem;
}

std::vector<std::byte> encodePipelineCacheFile(const PipelineCacheIdentity& id, std::span<const std::byte> data) {
    std::vector<std::byte> out;
    out.reserve(kPipelineCacheFileHeaderBytes + data.size());
    for (char c : kMagic) out.push_back(std::byte(c));
    for (uint32_t v : {kPipelineCacheFileVersion, id.vendorID, id.deviceID, id.driverVersion}) putLe(out, v, 4);
    for (uint8_t b : id.cacheUUID) out.push_back(std::byte(b));
    putLe(out, data.size(), 8);
    putLe(out, fnv1a64Update(kFnv1a64Basis, data.data(), data.size()), 8);
    out.insert(out.end(), data.begin(), data.end());
    return out;
}

std::string pipelineCacheFileProblem(std::span<const std::byte> file, const PipelineCacheIdentity& identity,
                                     std::span<const std::byte>* data) {
    Reader in{file};
    const auto magic = in.take(kMagic.size());
    if (!in.ok) return "truncated: " + std::to_string(file.size()) + " bytes, inside the magic";
    if (std::memcmp(magic.data(), kMagic.data(), kMagic.size()) != 0) return "not a Candela pipeline cache file (bad magic)";
    const uint32_t version = in.u32();
    PipelineCacheIdentity found{.vendorID = in.u32(), .deviceID = in.u32(), .driverVersion = in.u32()};
    found.cacheUUID = in.uuid();
    const uint64_t dataBytes = in.u64(), checksum = in.u64();
    if (!in.ok) return "truncated: " + std::to_string(file.size()) + " bytes, inside the " +
                       std::to_string(kPipelineCacheFileHeaderBytes) + "-byte header";
    if (version != kPipelineCacheFileVersion)
        return "file format version " + std::to_string(version) + ", expected " + std::to_string(kPipelineCacheFileVersion);
    if (std::string problem = identityProblem(found, identity, true); !problem.empty()) return problem;
    const size_t left = file.size() - in.offset;
    if (dataBytes > left) return "truncated: " + std::to_string(left) + " bytes of data, the header declares " + std::to_string(dataBytes);
    if (dataBytes < left) return std::to_string(left - dataBytes) + " unexpected bytes after the data";
    const std::span<const std::byte> payload = in.take(size_t(dataBytes));
    const uint64_t hash = fnv1a64Update(kFnv1a64Basis, payload.data(), payload.size());
    if (hash != checksum) return "checksum mismatch (stored " + hex16(checksum) + ", data hashes to " + hex16(hash) + "): corrupt file";
    if (std::string problem = pipelineCacheDataProblem(payload, identity); !problem.empty()) return problem;
    if (data) *data = payload;
    return {};
}

PipelineCacheFile::PipelineCacheFile(VkDevice device, const VkPhysicalDeviceProperties& properties, fs::path folder)
    : mDevice(device), mIdentity(PipelineCacheIdentity::of(properties)) {
    std::span<const std::byte> initial;
    std::vector<std::byte> file;
    if (folder.empty()) {
        mStatus = "off (in memory only)";
    } else {
        mPath = folder / pipelineCacheFileName(mIdentity);
        std::string problem;
        if (auto bytes = readFile(mPath, &problem)) {
            file = std::move(*bytes);
            problem = pipelineCacheFileProblem(file, mIdentity, &initial);
        }
        if (!problem.empty()) {
            initial = {};
            mStatus = mPath.string() + ": ignored (rewritten at exit): " + problem;
            log::info("pipeline cache " + mStatus);
        } else if (!file.empty()) {
            mStatus = "loaded " + formatBytes(initial.size()) + " from " + mPath.string();
        } else {
            mStatus = "none yet at " + mPath.string() + " (written at exit)";
        }
    }
    const VkPipelineCacheCreateInfo info{.sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO,
                                         .initialDataSize = initial.size(),
                                         .pInitialData = initial.data()};
    VK_CHECK(vkCreatePipelineCache(mDevice, &info, nullptr, &mCache));
    mLoaded.assign(initial.begin(), initial.end());
}

PipelineCacheFile::~PipelineCacheFile() {
    save();
    vkDestroyPipelineCache(mDevice, mCache, nullptr);
}

std::vector<std::byte> PipelineCacheFile::data() const {
    size_t size = 0;
    VK_CHECK(vkGetPipelineCacheData(mDevice, mCache, &size, nullptr));
    std::vector<std::byte> out(size);
    // The cache may grow between the two calls (another thread creating a pipeline): VK_INCOMPLETE
    // (not an error) then returns the part that fits, which is still a valid cache.
    VK_CHECK(vkGetPipelineCacheData(mDevice, mCache, &size, out.data()));
    out.resize(size);
    return out;
}

bool PipelineCacheFile::save() {
    if (mPath.empty()) return false;
    try {
        std::vector<std::byte> current = data();
        if (current == mLoaded) return false;
        if (current.size() > kPipelineCacheMaxDataBytes) {
            log::warn("pipeline cache: " + formatBytes(current.size()) + " of data, more than a cache file may hold; not written");
            return false;
        }
        const std::vector<std::byte> file = encodePipelineCacheFile(mIdentity, current);
        writeFileAtomically(mPath, [&](std::ostream& out) {
            out.write(reinterpret_cast<const char*>(file.data()), std::streamsize(file.size()));
        });
        mLoaded = std::move(current);
        return true;
    } catch (const std::exception& e) {
        log::warn(std::string("pipeline cache not saved: ") + e.what());
        return false;
    }
}

}  // namespace candela::vk
