// The pipeline cache file's checks (vk/pipeline_cache_file.h) on crafted bytes, without a device:
// the driver's VkPipelineCacheHeaderVersionOne, Candela's own header around it, every truncation,
// every flipped data byte, and file names that tell devices and drivers apart.
#include "vk/pipeline_cache_file.h"

#include <gtest/gtest.h>

#include <cstring>

namespace candela::vk {
namespace {

PipelineCacheIdentity identity() {
    PipelineCacheIdentity id{.vendorID = 0x10de, .deviceID = 0x2684, .driverVersion = 0x8b1c4000};
    for (uint8_t i = 0; i < VK_UUID_SIZE; ++i) id.cacheUUID[i] = uint8_t(0xa0 + i);
    return id;
}

// A driver's cache data: the 32-byte header of `id` (headerSize 32, version ONE) and `payload` bytes.
std::vector<std::byte> driverData(const PipelineCacheIdentity& id, size_t payload = 64, uint32_t headerSize = 32,
                                  uint32_t version = VK_PIPELINE_CACHE_HEADER_VERSION_ONE) {
    std::vector<std::byte> out(32 + payload);
    const uint32_t fields[] = {headerSize, version, id.vendorID, id.deviceID};
    std::memcpy(out.data(), fields, sizeof fields);  // little-endian host (x86, ARM)
    std::memcpy(out.data() + 16, id.cacheUUID.data(), VK_UUID_SIZE);
    for (size_t i = 0; i < payload; ++i) out[32 + i] = std::byte(i * 7 + 3);
    return out;
}

bool mentions(const std::string& problem, const char* part) { return problem.find(part) != std::string::npos; }

TEST(PipelineCacheHeader, AcceptsTheDevicesOwnHeader) {
    EXPECT_EQ(pipelineCacheDataProblem(driverData(identity()), identity()), "");
    EXPECT_EQ(pipelineCacheDataProblem(driverData(identity(), 0), identity()), "");  // header alone (lavapipe)
    EXPECT_EQ(pipelineCacheDataProblem(driverData(identity(), 64, 48), identity()), "");  // a longer header
}

TEST(PipelineCacheHeader, RefusesShortWrongSizeOtherVersionAndForeignHeaders) {
    const std::vector<std::byte> valid = driverData(identity());
    for (size_t size = 0; size < 32; ++size)
        EXPECT_TRUE(mentions(pipelineCacheDataProblem(std::span(valid).first(size), identity()), "shorter than")) << size;
    EXPECT_TRUE(mentions(pipelineCacheDataProblem(driverData(identity(), 64, 16), identity()), "declares 16 bytes"));
    EXPECT_TRUE(mentions(pipelineCacheDataProblem(driverData(identity(), 8, 41), identity()), "declares 41 bytes"));
    EXPECT_TRUE(mentions(pipelineCacheDataProblem(driverData(identity(), 64, 32, 2), identity()), "version 2"));
    PipelineCacheIdentity other = identity();
    other.vendorID = 0x1002;
    EXPECT_TRUE(mentions(pipelineCacheDataProblem(driverData(other), identity()), "another device"));
    other = identity();
    other.deviceID += 1;
    EXPECT_TRUE(mentions(pipelineCacheDataProblem(driverData(other), identity()), "another device"));
    for (size_t byte = 0; byte < VK_UUID_SIZE; ++byte) {
        other = identity();
        other.cacheUUID[byte] ^= 0x01;
        EXPECT_TRUE(mentions(pipelineCacheDataProblem(driverData(other), identity()), "pipeline cache UUID")) << byte;
    }
    // The driver's header does not hold the driver version: only Candela's does.
    other = identity();
    other.driverVersion += 1;
    EXPECT_EQ(pipelineCacheDataProblem(driverData(other), identity()), "");
}

TEST(PipelineCacheFileCheck, RoundTripsTheDriversData) {
    const std::vector<std::byte> data = driverData(identity(), 100);
    const std::vector<std::byte> file = encodePipelineCacheFile(identity(), data);
    ASSERT_EQ(file.size(), kPipelineCacheFileHeaderBytes + data.size());
    std::span<const std::byte> out;
    EXPECT_EQ(pipelineCacheFileProblem(file, identity(), &out), "");
    EXPECT_TRUE(std::equal(out.begin(), out.end(), data.begin(), data.end()));
}

TEST(PipelineCacheFileCheck, RefusesEveryTruncationTrailingBytesAndEveryFlippedByte) {
    const std::vector<std::byte> file = encodePipelineCacheFile(identity(), driverData(identity(), 40));
    for (size_t size = 0; size < file.size(); ++size) {
        std::span<const std::byte> out;
        const std::string problem = pipelineCacheFileProblem(std::span(file).first(size), identity(), &out);
        EXPECT_TRUE(mentions(problem, "truncated")) << size << ": " << problem;
        EXPECT_TRUE(out.empty());
    }
    std::vector<std::byte> longer = file;
    longer.push_back(std::byte(0));
    EXPECT_TRUE(mentions(pipelineCacheFileProblem(longer, identity(), nullptr), "unexpected bytes"));
    // Any flipped byte of the file is caught, by the field it lands in or by the checksum.
    for (size_t byte = 0; byte < file.size(); ++byte) {
        std::vector<std::byte> flipped = file;
        flipped[byte] ^= std::byte(0x10);
        EXPECT_NE(pipelineCacheFileProblem(flipped, identity(), nullptr), "") << "byte " << byte;
    }
    std::vector<std::byte> dataFlipped = file;
    dataFlipped.back() ^= std::byte(0x01);
    EXPECT_TRUE(mentions(pipelineCacheFileProblem(dataFlipped, identity(), nullptr), "checksum mismatch"));
}

TEST(PipelineCacheFileCheck, NamesWhatIsForeign) {
    const std::vector<std::byte> data = driverData(identity());
    PipelineCacheIdentity other = identity();
    other.driverVersion += 1;
    EXPECT_TRUE(mentions(pipelineCacheFileProblem(encodePipelineCacheFile(other, data), identity(), nullptr), "another driver version"));
    other = identity();
    other.cacheUUID[15] ^= 0x80;
    EXPECT_TRUE(mentions(pipelineCacheFileProblem(encodePipelineCacheFile(other, data), identity(), nullptr), "pipeline cache UUID"));
    other = identity();
    other.vendorID = 0x8086;
    EXPECT_TRUE(mentions(pipelineCacheFileProblem(encodePipelineCacheFile(other, data), identity(), nullptr), "another device"));
    std::vector<std::byte> file = encodePipelineCacheFile(identity(), data);
    file[0] = std::byte('X');
    EXPECT_TRUE(mentions(pipelineCacheFileProblem(file, identity(), nullptr), "bad magic"));
    file = encodePipelineCacheFile(identity(), data);
    file[12] = std::byte(2);  // the file format version
    EXPECT_TRUE(mentions(pipelineCacheFileProblem(file, identity(), nullptr), "file format version 2"));
    // A file whose own header is right but whose driver data is another device's.
    other = identity();
    other.deviceID = 1;
    EXPECT_TRUE(mentions(pipelineCacheFileProblem(encodePipelineCacheFile(identity(), driverData(other)), identity(), nullptr),
                         "the driver's header: made for another device"));
}

TEST(PipelineCacheFileCheck, FileNamesTellDevicesAndDriversApart) {
    const std::string name = pipelineCacheFileName(identity());
    EXPECT_EQ(name, "pipelines-000010de-00002684-8b1c4000-a0a1a2a3a4a5a6a7a8a9aaabacadaeaf.bin");
    PipelineCacheIdentity other = identity();
    other.driverVersion += 1;
    EXPECT_NE(pipelineCacheFileName(other), name);
    other = identity();
    other.cacheUUID[7] ^= 1;
    EXPECT_NE(pipelineCacheFileName(other), name);
    other = identity();
    other.deviceID ^= 1;
    EXPECT_NE(pipelineCacheFileName(other), name);
}

}  // namespace
}  // namespace candela::vk
