// ParameterRegistry: the user's values over the bytes a pass fills, and what the panel sees.
#include "shader/parameter_registry.h"

#include <gtest/gtest.h>

#include <cstring>

namespace candela::shader {
namespace {

struct Block {
    float tint[4] = {0.1f, 0.2f, 0.3f, 1.0f};
    float exposure = 0.0f;
    uint32_t flag = 0;
    float matrix[16] = {};
};

std::vector<BlockMember> layout() {
    BlockMember tint{.name = "p.tint", .offset = 0, .size = 16, .type = BaseType::Float, .vectorSize = 4};
    tint.annotation.color = true;
    BlockMember exposure{.name = "p.exposure", .offset = 16, .size = 4, .type = BaseType::Float};
    BlockMember flag{.name = "p.flag", .offset = 20, .size = 4, .type = BaseType::Bool};
    BlockMember matrix{.name = "p.matrix", .offset = 24, .size = 64, .type = BaseType::Float, .vectorSize = 4, .columns = 4};
    BlockMember hidden{.name = "p.hidden", .offset = 20, .size = 4, .type = BaseType::UInt};
    hidden.annotation.ignore = true;
    return {tint, exposure, flag, matrix, hidden};
}

TEST(ParameterRegistry, RecordsEditableMembersAndValues) {
    ParameterRegistry registry;
    Block block;
    const auto members = layout();
    EXPECT_FALSE(registry.apply("tonemap", "Push", members, block));
    const ParameterRegistry::Block* recorded = registry.find("tonemap", "Push");
    ASSERT_NE(recorded, nullptr);
    ASSERT_EQ(recorded->members.size(), 3u);  // no matrix, nothing /*Ignore*/
    EXPECT_EQ(recorded->members[0].name, "p.tint");
    EXPECT_EQ(recorded->values.size(), sizeof(Block));
    EXPECT_EQ(std::memcmp(recorded->values.data(), &block, sizeof(Block)), 0);
}

TEST(ParameterRegistry, UserValuesOverrideUntilReset) {
    ParameterRegistry registry;
    const auto members = layout();
    const float ev = 2.5f;
    registry.set("tonemap", "Push", members[1], std::as_bytes(std::span(&ev, 1)));
    EXPECT_TRUE(registry.isSet("tonemap", "Push", "p.exposure"));
    Block block;
    EXPECT_TRUE(registry.apply("tonemap", "Push", members, block));
    EXPECT_EQ(block.exposure, 2.5f);
    EXPECT_EQ(block.tint[0], 0.1f);  // untouched
    // Applying again to bytes that already hold the value changes nothing.
    EXPECT_FALSE(registry.apply("tonemap", "Push", members, block));
    // Other blocks and passes are not affected.
    Block other;
    EXPECT_FALSE(registry.apply("skybox", "Push", members, other));
    EXPECT_EQ(other.exposure, 0.0f);
    registry.reset("tonemap", "Push", "p.exposure");
    Block fresh;
    EXPECT_FALSE(registry.apply("tonemap", "Push", members, fresh));
    EXPECT_EQ(fresh.exposure, 0.0f);
}

TEST(ParameterRegistry, RejectsWrongSizesAndUneditableMembers) {
    ParameterRegistry registry;
    const auto members = layout();
    const double wide = 1.0;
    EXPECT_THROW(registry.set("t", "Push", members[1], std::as_bytes(std::span(&wide, 1))), std::invalid_argument);
    const float m[16] = {};
    EXPECT_THROW(registry.set("t", "Push", members[3], std::as_bytes(std::span(m))), std::invalid_argument);
    const uint32_t h = 1;
    EXPECT_THROW(registry.set("t", "Push", members[4], std::as_bytes(std::span(&h, 1))), std::invalid_argument);
}

TEST(ParameterRegistry, ValuesBeyondASmallerBlockAreSkipped) {
    ParameterRegistry registry;
    const auto members = layout();
    const uint32_t on = 1;
    registry.set("t", "Push", members[2], std::as_bytes(std::span(&on, 1)));
    std::byte small[8] = {};
    EXPECT_FALSE(registry.apply("t", "Push", members, std::span(small)));
    EXPECT_TRUE(registry.find("t", "Push")->members.empty());  // none fits in 8 bytes
}

TEST(ParameterRegistry, FramesMarkWhichBlocksAreCurrent) {
    ParameterRegistry registry;
    Block block;
    registry.beginFrame();
    registry.apply("a", "Push", layout(), block);
    registry.beginFrame();
    registry.apply("b", "Push", layout(), block);
    EXPECT_EQ(registry.find("a", "Push")->frame, 1u);
    EXPECT_EQ(registry.find("b", "Push")->frame, 2u);
    EXPECT_EQ(registry.frame(), 2u);
    ASSERT_EQ(registry.blocks().size(), 2u);
    EXPECT_EQ(registry.blocks()[0].pass, "a");
}

}  // namespace
}  // namespace candela::shader
