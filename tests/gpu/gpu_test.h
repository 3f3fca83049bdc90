#pragma once
// Fixture for GPU tests: a vk::Context on the default device (lavapipe in CI) with the Khronos
// validation layer and synchronization validation always on. Any validation message fails the test.
// With CANDELA_BEST_PRACTICES=1 (ctest's lavapipe run of the suite) the layer's best-practices
// checks are on too, and only the warnings listed in bestPracticesNotApplicable — each with the
// reason it does not apply (docs/testing.md) — are let through.

#include "options/shading_path.h"
#include "vk/commands.h"
#include "vk/context.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace candela::test {

// Best-practices warnings that do not apply to Candela; everything else fails the test.
inline bool bestPracticesNotApplicable(const std::string& text) {
    const auto has = [&](const char* part) { return text.find(part) != std::string::npos; };
    // VK_EXT_validation_features and VK_EXT_debug_utils are "for debugging": enabling validation is
    // exactly that (debug_utils also names objects and labels passes for capture tools).
    if (has("[ UNASSIGNED-BestPractices-vkCreateInstance-specialuse-extension-debugging ]")) return true;
    // The layer (1.3.239) expects the legacy VK_ACCESS_2_SHADER_READ_BIT for an image in
    // SHADER_READ_ONLY_OPTIMAL; the synchronization2 bit for sampling, SHADER_SAMPLED_READ, is one
    // of the bits SHADER_READ stands for and the more precise of the two.
    if (has("[ UNASSIGNED-BestPractices-ImageBarrierAccessLayout ]") &&
        has("| VK_ACCESS_2_SHADER_SAMPLED_READ_BIT: accessMask is vkCmdPipelineBarrier2, but for layout "
            "VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL expected accessMask are "
            "VK_ACCESS_2_INPUT_ATTACHMENT_READ_BIT|VK_ACCESS_2_SHADER_READ_BIT."))
        return true;
    return false;
}

// Makes copy results visible to host reads after the fence (a test's read-back).
inline void copiesToHostBarrier(VkCommandBuffer cmd) {
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_HOST_READ_BIT);
}

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override {
        mContext = std::make_unique<vk::Context>(vk::ContextDesc{.validation = true});
        ASSERT_TRUE(mContext->validationEnabled());
    }
    void TearDown() override {
        if (!mContext) return;
        mContext->waitIdleAndCollect();
        if (mExpectValidationMessages) return;
        for (const vk::ValidationMessage& m : mContext->validationMessages())
            if (!bestPracticesNotApplicable(m.text)) ADD_FAILURE() << "validation: " << m.text;
    }
    vk::Context& context() { return *mContext; }
    // The shading paths the device runs: forward, and the visibility path unless the device lacks
    // what it needs (DeviceChoices::visibilityUnsupported).
    std::vector<options::ShadingPath> shadingPaths() {
        std::vector<options::ShadingPath> out{options::ShadingPath::Forward};
        if (context().choices().visibilityUnsupported.empty()) out.push_back(options::ShadingPath::Visibility);
        return out;
    }
    // For the one test that proves validation catches a missing barrier.
    void expectValidationMessages() { mExpectValidationMessages = true; }

    std::unique_ptr<vk::Context> mContext;
    bool mExpectValidationMessages = false;
};

}  // namespace candela::test
