#include "graph/graph_types.h"

namespace candela::graph {

namespace {

// Shader stages implied by the pass type when a usage reaches the resource through a shader.
VkPipelineStageFlags2 shaderStages(PassType passType) {
    switch (passType) {
    case PassType::Graphics:
        return VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    case PassType::Compute:
        return VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    case PassType::Transfer:
        // A transfer pass has no shaders (RenderGraph refuses shader usages in one).
        return VK_PIPELINE_STAGE_2_NONE;
    }
    return VK_PIPELINE_STAGE_2_NONE;
}

}  // namespace

const char* usageName(Usage usage) {
    switch (usage) {
    case Usage::Sampled: return "Sampled";
    case Usage::StorageRead: return "StorageRead";
    case Usage::StorageWrite: return "StorageWrite";
    case Usage::StorageReadWrite: return "StorageReadWrite";
    case Usage::ColorAttachment: return "ColorAttachment";
    case Usage::DepthAttachment: return "DepthAttachment";
    case Usage::DepthRead: return "DepthRead";
    case Usage::ResolveAttachment: return "ResolveAttachment";
    case Usage::TransferSrc: return "TransferSrc";
    case Usage::TransferDst: return "TransferDst";
    case Usage::Uniform: return "Uniform";
    case Usage::Vertex: return "Vertex";
    case Usage::Index: return "Index";
    case Usage::Indirect: return "Indirect";
    }
    return "Unknown";
}

bool usageWrites(Usage usage) {
    switch (usage) {
    case Usage::StorageWrite:
    case Usage::StorageReadWrite:
    case Usage::ColorAttachment:
    case Usage::DepthAttachment:
    case Usage::ResolveAttachment:
    case Usage::TransferDst:
        return true;
    default:
        return false;
    }
}

AccessSync accessSync(Usage usage, PassType passType, ResourceKind kind,
                      VkPipelineStageFlags2 stageOverride, bool depthFormat) {
    const VkPipelineStageFlags2 shader = stageOverride != 0 ? stageOverride : shaderStages(passType);
    constexpr VkPipelineStageFlags2 kDepthTests =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    AccessSync sync;
    switch (usage) {
    case Usage::Sampled:
        sync = {shader, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                depthFormat ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL
                            : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        break;
    case Usage::StorageRead:
        sync = {shader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_GENERAL};
        break;
    case Usage::StorageWrite:
        sync = {shader, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL};
        break;
    case Usage::StorageReadWrite:
        sync = {shader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_IMAGE_LAYOUT_GENERAL};
        break;
    case Usage::ColorAttachment:
        sync = {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        break;
    case Usage::DepthAttachment:
        sync = {kDepthTests,
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL};
        break;
    case Usage::ResolveAttachment:
        // Resolves run in the colour-attachment-output stage as attachment writes, for colour and
        // depth alike (Vulkan spec, "Render Pass Load/Store/Resolve Operations").
        sync = {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        break;
    case Usage::DepthRead:
        sync = {kDepthTests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL};
        break;
    case Usage::TransferSrc:
        sync = {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
        break;
    case Usage::TransferDst:
        sync = {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
        break;
    case Usage::Uniform:
        sync = {shader, VK_ACCESS_2_UNIFORM_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED};
        break;
    case Usage::Vertex:
        sync = {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT,
                VK_IMAGE_LAYOUT_UNDEFINED};
        break;
    case Usage::Index:
        sync = {VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT, VK_ACCESS_2_INDEX_READ_BIT,
                VK_IMAGE_LAYOUT_UNDEFINED};
        break;
    case Usage::Indirect:
        sync = {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
                VK_IMAGE_LAYOUT_UNDEFINED};
        break;
    }
    // Buffers have no layout.
    if (kind == ResourceKind::Buffer) sync.layout = VK_IMAGE_LAYOUT_UNDEFINED;
    return sync;
}

uint32_t formatTexelSize(VkFormat format) {
    switch (format) {
    case VK_FORMAT_R8_UNORM:
    case VK_FORMAT_R8_SNORM:
    case VK_FORMAT_R8_UINT:
    case VK_FORMAT_R8_SRGB:
    case VK_FORMAT_S8_UINT:
        return 1;
    case VK_FORMAT_R8G8_UNORM:
    case VK_FORMAT_R8G8_SNORM:
    case VK_FORMAT_R8G8_UINT:
    case VK_FORMAT_R8G8_SRGB:
    case VK_FORMAT_R16_SFLOAT:
    case VK_FORMAT_R16_UNORM:
    case VK_FORMAT_R16_UINT:
    case VK_FORMAT_D16_UNORM:
        return 2;
    case VK_FORMAT_D16_UNORM_S8_UINT:
        return 3;
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SNORM:
    case VK_FORMAT_R8G8B8A8_UINT:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R16G16_UNORM:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_R32_SINT:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_X8_D24_UNORM_PACK32:
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
    case VK_FORMAT_E5B9G9R9_UFLOAT_PACK32:
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
    case VK_FORMAT_A2R10G10B10_UNORM_PACK32:
        return 4;
    case VK_FORMAT_D32_SFLOAT_S8_UINT:
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R16G16B16A16_UNORM:
    case VK_FORMAT_R32G32_SFLOAT:
    case VK_FORMAT_R32G32_UINT:
        return 8;
    case VK_FORMAT_R32G32B32_SFLOAT:
        return 12;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_UINT:
        return 16;
    default:
        return 0;
    }
}

bool isDepthFormat(VkFormat format) {
    switch (format) {
    case VK_FORMAT_D16_UNORM:
    case VK_FORMAT_D16_UNORM_S8_UINT:
    case VK_FORMAT_X8_D24_UNORM_PACK32:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_D32_SFLOAT_S8_UINT:
        return true;
    default:
        return false;
    }
}

}  // namespace candela::graph
