#pragma once
// Fixture for GPU tests: a vk::Context on the default device (lavapipe in CI) with the Khronos
// validation layer and synchronization validation always on. Any validation message fails the test.

#include "vk/context.h"

#include <gtest/gtest.h>

#include <memory>

namespace candela::test {

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
        for (const vk::ValidationMessage& m : mContext->validationMessages()) ADD_FAILURE() << "validation: " << m.text;
    }
    vk::Context& context() { return *mContext; }
    // For the one test that proves validation catches a missing barrier.
    void expectValidationMessages() { mExpectValidationMessages = true; }

    std::unique_ptr<vk::Context> mContext;
    bool mExpectValidationMessages = false;
};

}  // namespace candela::test
