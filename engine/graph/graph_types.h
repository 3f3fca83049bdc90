#pragma once
// Vocabulary of the render graph: handles, resource descriptions, usages and sync states.
// Pure data. Vulkan enums are used as values only; nothing here calls Vulkan.

#include <vulkan/vulkan_core.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace candela::graph {

inline constexpr uint32_t kInvalidIndex = std::numeric_limits<uint32_t>::max();

enum class ResourceKind : uint8_t { Texture, Buffer };

// What a pass records: graphics (draws inside dynamic rendering), compute, or transfer.
enum class PassType : uint8_t { Graphics, Compute, Transfer };

// Description of a texture. A cube map has cube = true and arrayLayers a multiple of 6.
// samples > 1: a multisampled colour or depth attachment (one mip, one layer, 2D).
struct TextureDesc {
    uint32_t width = 1;
    uint32_t height = 1;
    uint32_t depth = 1;
    uint32_t mipLevels = 1;
    uint32_t arrayLayers = 1;
    VkFormat format = VK_FORMAT_UNDEFINED;
    bool cube = false;
    uint32_t samples = 1;
};

struct BufferDesc {
    VkDeviceSize size = 0;
};

// Versioned handles (Filament's FrameGraph idea): every write returns a new version, so the order
// of passes follows from which version each pass reads, never from the order passes were added.
struct TextureId {
    uint32_t index = kInvalidIndex;
    uint32_t version = 0;
    bool valid() const { return index != kInvalidIndex; }
    friend bool operator==(const TextureId&, const TextureId&) = default;
};

struct BufferId {
    uint32_t index = kInvalidIndex;
    uint32_t version = 0;
    bool valid() const { return index != kInvalidIndex; }
    friend bool operator==(const BufferId&, const BufferId&) = default;
};

// How a pass touches a resource. Together with the pass type (and an optional explicit stage
// mask) a usage determines the pipeline stages, access flags and image layout of the access.
enum class Usage : uint8_t {
    Sampled,           // texture read through a sampler
    StorageRead,       // storage image / storage buffer, read only
    StorageWrite,      // storage image / storage buffer, write only
    StorageReadWrite,  // storage image / storage buffer, read and write
    ColorAttachment,   // colour attachment (write; reads too when the previous contents are loaded)
    DepthAttachment,   // depth attachment with depth writes
    DepthRead,         // depth attachment, test only (read-only layout)
    ResolveAttachment, // single-sample image a multisampled colour attachment is resolved into (write)
    TransferSrc,       // copy/blit source
    TransferDst,       // copy/blit/clear destination
    Uniform,           // uniform buffer
    Vertex,            // vertex buffer
    Index,             // index buffer
    Indirect,          // indirect draw/dispatch arguments
};

const char* usageName(Usage usage);
bool usageWrites(Usage usage);

// Whether a write keeps the previous contents (load, read-modify-write, partial update) or
// replaces them entirely. A preserving write depends on the producer of the previous version.
enum class WriteMode : uint8_t { Preserve, Discard };

// Where a resource was last touched: the pipeline stages, the accesses and, for images, the layout.
// Used for imported resources (initial and required final state) and for barrier endpoints.
struct ResourceState {
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    friend bool operator==(const ResourceState&, const ResourceState&) = default;
};

// The synchronisation an access needs, derived from (usage, pass type, optional stage override).
struct AccessSync {
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // UNDEFINED for buffers
};

// Derives the sync info of one access. `stageOverride` replaces the shader stages implied by the
// pass type for Sampled/Storage*/Uniform usages (0 = derive: graphics → vertex|fragment shader,
// compute → compute shader). `depthFormat` selects depth layouts for sampled depth textures.
AccessSync accessSync(Usage usage, PassType passType, ResourceKind kind,
                      VkPipelineStageFlags2 stageOverride = 0, bool depthFormat = false);

// Bytes per texel of an uncompressed format (0 if unknown). Used by the default size model.
uint32_t formatTexelSize(VkFormat format);
bool isDepthFormat(VkFormat format);

// Graph misuse: the message names the pass and the resource involved.
class GraphError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace candela::graph
