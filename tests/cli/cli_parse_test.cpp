#include "bench_cli.h"
#include "cli.h"
#include "core/errors.h"

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

TEST(CliParse, SequenceFileNames) {
    EXPECT_EQ(sequenceFileName("frame_%04d.png", 7), "frame_0007.png");
    EXPECT_EQ(sequenceFileName("f%d.exr", 12345), "f12345.exr");
    EXPECT_EQ(sequenceFileName("100%%_%02d.png", 3), "100%_03.png");
    EXPECT_EQ(sequenceFileName("%03d.png", 1234), "1234.png");  // wider than the field: not cut
    EXPECT_THROW(sequenceFileName("frame.png", 0), UserError);
    EXPECT_THROW(sequenceFileName("%d_%d.png", 0), UserError);
    EXPECT_THROW(sequenceFileName("%4d.png", 0), UserError);
    EXPECT_THROW(sequenceFileName("%s.png", 0), UserError);
    EXPECT_THROW(sequenceFileName("trailing%", 0), UserError);
}

TEST(CliParse, AnimationFlags) {
    const Command c = parseCommandLine({"render", "--animation", "Walk,2", "--animation", "all", "--time", "1e6", "--frames", "4",
                                        "--fps", "24", "--turntable", "360"});
    EXPECT_EQ(c.render.animations, (std::vector<std::string>{"Walk", "2", "all"}));
    EXPECT_EQ(c.render.time, 1e6);
    EXPECT_EQ(c.render.frames, 4u);
    EXPECT_EQ(c.render.fps, 24.0);
    EXPECT_EQ(c.render.turntableDegrees, 360.0f);
    EXPECT_EQ(parseCommandLine({"render"}).render.frames, 1u);
    EXPECT_THROW(parseCommandLine({"view", "--fps", "24"}), UserError);  // sequences are render's
}

TEST(CliParse, SceneLights) {
    EXPECT_TRUE(parseCommandLine({"render"}).render.sceneLights);
    EXPECT_FALSE(parseCommandLine({"render", "--scene-lights", "off"}).render.sceneLights);
    EXPECT_TRUE(parseCommandLine({"bench", "--scene-lights=on"}).bench.sceneLights);
    EXPECT_FALSE(parseCommandLine({"view", "--scene-lights", "off"}).view.sceneLights);
    EXPECT_THROW(parseCommandLine({"render", "--scene-lights", "no"}), UserError);
}

TEST(CliParse, BenchColdPassesOnTheRenderFlagsAlone) {
    const Command c = parseCommandLine({"bench", "--cold", "3", "--scene", "x.glb", "--frames=5", "--json", "--width", "64",
                                        "--explain", "--in-flight", "--frames", "2", "--ibl-cache", "off"});
    EXPECT_EQ(c.bench.cold, 3u);
    EXPECT_EQ(c.arguments.size(), 14u);
    EXPECT_EQ(coldRenderArguments(c.arguments),
              (std::vector<std::string>{"--scene", "x.glb", "--width", "64", "--ibl-cache", "off"}));
    EXPECT_EQ(coldRenderArguments({"--cold=2"}), std::vector<std::string>{});
    EXPECT_EQ(parseCommandLine({"bench"}).bench.cold, 0u);
}

TEST(CliParse, Errors) {
    EXPECT_THROW(parseCommandLine({"render", "--bogus"}), UserError);
    EXPECT_THROW(parseCommandLine({"bench", "stray"}), UserError);
    EXPECT_THROW(parseCommandLine({"render", "a.glb", "--grid", "3"}), UserError);
    EXPECT_THROW(parseCommandLine({"view", "--variant", "all"}), UserError);  // render only
    EXPECT_THROW(parseCommandLine({"info", "--out", "x.png"}), UserError);
    EXPECT_THROW(parseCommandLine({"render", "--out"}), UserError);
    // Checked while parsing, before anything loads: --grid sizes the built-in grid only.
    EXPECT_THROW(parseCommandLine({"view", "a.glb", "--grid", "3"}), UserError);
    EXPECT_THROW(parseCommandLine({"render", "--grid", "7", "--scene", "a.glb"}), UserError);
    EXPECT_THROW(parseCommandLine({"bench", "--scene-index", "1"}), UserError);
}

}  // namespace
}  // namespace candela::app
