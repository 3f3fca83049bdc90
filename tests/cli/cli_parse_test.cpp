#include "cli.h"
#include "core/check.h"

#include <gtest/gtest.h>

namespace candela::app {
namespace {

TEST(CliParse, RenderDefaultsAndValues) {
    const Command c = parseCommandLine({"render", "--width", "640", "--height=480", "--out", "a.exr", "--disable-pass",
                                        "encode", "--disable-pass", "pattern", "--validate", "--device", "llvmpipe"});
    ASSERT_EQ(c.kind, Command::Kind::Render);
    EXPECT_EQ(c.render.width, 640u);
    EXPECT_EQ(c.render.height, 480u);
    EXPECT_EQ(c.render.out, "a.exr");
    EXPECT_EQ(c.render.disabledPasses, (std::vector<std::string>{"encode", "pattern"}));
    EXPECT_TRUE(c.render.common.validate);
    EXPECT_EQ(c.render.common.device, "llvmpipe");
}

TEST(CliParse, NoArgumentsOrHelpIsHelp) {
    EXPECT_EQ(parseCommandLine({}).kind, Command::Kind::Help);
    EXPECT_EQ(parseCommandLine({"--help"}).kind, Command::Kind::Help);
    EXPECT_EQ(parseCommandLine({"render", "--help"}).kind, Command::Kind::Help);
}

TEST(CliParse, Dimensions) {
    EXPECT_EQ(parseDimension("--width", "0"), 0u);  // range is checked against the device later
    EXPECT_EQ(parseDimension("--width", "4294967295"), 4294967295u);
    EXPECT_THROW(parseDimension("--width", "4294967296"), UserError);
    EXPECT_THROW(parseDimension("--width", "-1"), UserError);
    EXPECT_THROW(parseDimension("--width", ""), UserError);
    EXPECT_THROW(parseDimension("--width", "1e3"), UserError);
}

TEST(CliParse, Errors) {
    EXPECT_THROW(parseCommandLine({"render", "--bogus"}), UserError);
    EXPECT_THROW(parseCommandLine({"render", "stray"}), UserError);
    EXPECT_THROW(parseCommandLine({"info", "--out", "x.png"}), UserError);
    EXPECT_THROW(parseCommandLine({"render", "--out"}), UserError);
}

}  // namespace
}  // namespace candela::app
