#pragma once
// PipelineCacheFile: the device's VkPipelineCache (every pipeline is created through it:
// vk/pipeline.cpp), loaded at start-up from a file in the user's cache folder and written back at
// shutdown, so a launch reuses what earlier ones compiled. One per vk::Context.
//
// The file is keyed by the device (its name holds the vendor, device, driver version and
// pipelineCacheUUID) and checked before the driver sees a byte of it: a file that is unreadable,
// truncated, corrupt (checksum), made by another Candela file version or for another device or
// driver is ignored — one line through log::info (shown with --verbose), never an error — and
// replaced at shutdown. Set ContextDesc::pipelineCacheFolder empty for a cache in memory only.
//
// File layout, all integers little-endian, no padding (kPipelineCacheFileHeaderBytes = 60):
//     magic           12 bytes  "CANDELA-PSO\0"
//     version         u32       kPipelineCacheFileVersion (1)
//     vendorID        u32       VkPhysicalDeviceProperties::vendorID
//     deviceID        u32       ::deviceID
//     driverVersion   u32       ::driverVersion
//     cacheUUID       16 bytes  ::pipelineCacheUUID
//     dataBytes       u64       ≤ kPipelineCacheMaxDataBytes; exactly the bytes left in the file
//     checksum        u64       FNV-1a 64 of the data
//     data            the driver's vkGetPipelineCacheData, which starts with its
//                     VkPipelineCacheHeaderVersionOne (checked too: pipelineCacheDataProblem)

#include <vulkan/vulkan_core.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace candela::vk {

inline constexpr uint32_t kPipelineCacheFileVersion = 1;
inline constexpr size_t kPipelineCacheFileHeaderBytes = 60;
// A larger file is not read (nor a larger cache written): far above what a renderer's few hundred
// pipelines take, and a bound on what a damaged file can make us allocate.
inline constexpr uint64_t kPipelineCacheMaxDataBytes = uint64_t(256) << 20;

// The device a pipeline cache is valid for.
struct PipelineCacheIdentity {
    uint32_t vendorID = 0;
    uint32_t deviceID = 0;
    uint32_t driverVersion = 0;
    std::array<uint8_t, VK_UUID_SIZE> cacheUUID{};
    static PipelineCacheIdentity of(const VkPhysicalDeviceProperties& properties);
    bool operator==(const PipelineCacheIdentity&) const = default;
};

// "pipelines-<vendorID>-<deviceID>-<driverVersion>-<cacheUUID>.bin", each in lowercase hex
// (8, 8, 8 and 32 digits): another device or driver uses another file.
std::string pipelineCacheFileName(const PipelineCacheIdentity& identity);

// Why the driver's cache data `data` is not for `identity`, or "" if its
// VkPipelineCacheHeaderVersionOne says it is: at least 32 bytes, headerSize 32..size,
// headerVersion ONE, then vendorID, deviceID and pipelineCacheUUID equal. Pure.
std::string pipelineCacheDataProblem(std::span<const std::byte> data, const PipelineCacheIdentity& identity);

// The file's bytes for the driver's cache data `data` of device `identity`.
std::vector<std::byte> encodePipelineCacheFile(const PipelineCacheIdentity& identity, std::span<const std::byte> data);

// Checks the whole file `file` (its header, size, checksum, then the driver's header inside):
// "" and the driver's data in *data when it is valid for `identity`, else why not (one line: bad
// magic, other version, other device or driver, truncated, trailing bytes, checksum mismatch...).
// Never reads out of bounds. Pure.
std::string pipelineCacheFileProblem(std::span<const std::byte> file, const PipelineCacheIdentity& identity,
                                     std::span<const std::byte>* data);

class PipelineCacheFile {
public:
    // Creates `device`'s pipeline cache, with the data of folder / pipelineCacheFileName(...) when
    // that file is valid for this device (else empty; see the top). `folder` empty: no file. The
    // folder is created only when the cache is written.
    PipelineCacheFile(VkDevice device, const VkPhysicalDeviceProperties& properties, std::filesystem::path folder);
    // Writes the cache back (save()) and destroys it. Precondition: no pipeline is being created.
    ~PipelineCacheFile();
    PipelineCacheFile(const PipelineCacheFile&) = delete;
    PipelineCacheFile& operator=(const PipelineCacheFile&) = delete;

    // The cache to pass to vkCreate*Pipelines. Internally synchronized: any thread may use it.
    VkPipelineCache handle() const { return mCache; }
    // The file; empty when there is none.
    const std::filesystem::path& path() const { return mPath; }
    // What became of the file at start-up, one line for --explain ("loaded 1.2 MiB from PATH",
    // "PATH: ignored: ...", "none yet at PATH", "off (in memory only)").
    const std::string& status() const { return mStatus; }
    // Bytes of the driver's data loaded from the file (0: none).
    size_t loadedBytes() const { return mLoaded.size(); }
    // The driver's current cache data.
    std::vector<std::byte> data() const;
    // Writes the data atomically to the file when it differs from what was loaded. Never throws:
    // a failure (read-only folder, disk full) is one warning. Returns whether it wrote the file.
    bool save();

private:
    VkDevice mDevice = VK_NULL_HANDLE;
    PipelineCacheIdentity mIdentity;
    std::filesystem::path mPath;
    std::string mStatus;
    std::vector<std::byte> mLoaded;  // the driver's data as loaded (or last saved)
    VkPipelineCache mCache = VK_NULL_HANDLE;
};

}  // namespace candela::vk
