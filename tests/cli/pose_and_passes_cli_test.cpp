// `candela render` on the shared samples where a request cannot be met literally (#31): animations
// that drive the same channels get one warning saying which and which wins (and nothing for one
// animation or disjoint ones); `--disable-pass` of a pass the frame can do without draws the frame
// without it, and of one it cannot do without is one line naming that pass.
#include "run_candela.h"
#include "test_paths.h"
#include "temp_dir.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using candela::test::Result;
using candela::test::run;

fs::path model(const std::string& relative) { return ::candela::test::sharedAssets() / "models" / relative; }

#define REQUIRE_MODEL(path)                                                           \
    do {                                                                              \
        if (!fs::exists(path)) GTEST_SKIP() << "shared asset missing: " << (path);   \
    } while (0)

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    size_t at = 0;
    while (at < text.size()) {
        const size_t end = text.find('\n', at);
        out.push_back(text.substr(at, end - at));
        at = end == std::string::npos ? text.size() : end + 1;
    }
    return out;
}

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;
    // Pixels unlike the first (the corner: background).
    int unlikeCorner() const {
        int n = 0;
        for (size_t i = 4; i < rgba.size(); i += 4) n += std::memcmp(&rgba[i], rgba.data(), 4) != 0;
        return n;
    }
};

Image readPng(const fs::path& path) {
    Image image;
    int channels = 0;
    uint8_t* pixels = stbi_load(path.c_str(), &image.width, &image.height, &channels, 4);
    if (!pixels) return image;
    image.rgba.assign(pixels, pixels + size_t(image.width) * size_t(image.height) * 4);
    stbi_image_free(pixels);
    return image;
}

class PoseAndPasses : public testing::Test {
protected:
    // Renders `scene` at 64×48 (no environment: fast) with `flags` into `name`.
    Result render(const fs::path& scene, const std::string& flags, const std::string& name) {
        return run("render --validate --env none --width 64 --height 48 --scene '" + scene.string() + "' " + flags +
                   " --out '" + (mDir.path() / name).string() + "'");
    }
    Image image(const std::string& name) { return readPng(mDir.path() / name); }

    candela::test::TempDir mDir{"candela_pose_passes"};
};

TEST_F(PoseAndPasses, OverlappingAnimationsAreOneWarningNamingTheWinner) {
    const fs::path fox = model("Fox/glTF-Binary/Fox.glb");
    REQUIRE_MODEL(fox);
    const Result all = render(fox, "--animation all --time 0.4", "all.png");
    ASSERT_EQ(all.exitCode, 0) << all.stderrText;
    const std::vector<std::string> said = lines(all.stderrText);
    ASSERT_EQ(said.size(), 1u) << all.stderrText;
    EXPECT_EQ(said[0].rfind("candela: warning: " + fox.string() + ": animations 'Survey', 'Walk' and 'Run' drive the same ", 0), 0u)
        << said[0];
    EXPECT_NE(said[0].find("rotation of '"), std::string::npos) << said[0];
    EXPECT_NE(said[0].find("; 'Run' wins (the last in the file"), std::string::npos) << said[0];
    // Named in another order, the same animations play the same way and say the same.
    const Result named = render(fox, "--animation Run,Survey,Walk --time 0.4", "named.png");
    EXPECT_EQ(named.stderrText, all.stderrText);
    EXPECT_EQ(image("named.png").rgba, image("all.png").rgba);

    // One animation, the default, or none: nothing to say.
    for (const char* flags : {"--animation Walk", "", "--animation none", "--animation 1,none"}) {
        const Result one = render(fox, flags, "one.png");
        EXPECT_EQ(one.exitCode, 0) << flags;
        EXPECT_EQ(one.stderrText, "") << flags;
    }
}

TEST_F(PoseAndPasses, AnimationsOnDisjointChannelsPlayQuietly) {
    const fs::path interpolation = model("InterpolationTest/glTF-Binary/InterpolationTest.glb");
    REQUIRE_MODEL(interpolation);
    const Result r = render(interpolation, "--animation all --time 0.9", "all.png");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.stderrText, "");
}

TEST_F(PoseAndPasses, TransmissionWithoutItsBackgroundSeesOnlyTheBackdrop) {
    const fs::path transmission = model("TransmissionTest/glTF-Binary/TransmissionTest.glb");
    REQUIRE_MODEL(transmission);
    const Result normal = render(transmission, "", "normal.png");
    ASSERT_EQ(normal.exitCode, 0) << normal.stderrText;
    const Result off = render(transmission, "--disable-pass transmission_background", "off.png");
    ASSERT_EQ(off.exitCode, 0) << off.stderrText;
    EXPECT_EQ(off.stderrText, "");
    const Image a = image("normal.png"), b = image("off.png");
    ASSERT_EQ(b.width, 64);
    ASSERT_EQ(b.height, 48);
    EXPECT_GT(b.unlikeCorner(), 64 * 48 / 10) << "the frame is drawn";
    EXPECT_NE(a.rgba, b.rgba) << "the transmissive spheres no longer see the scene behind them";
}

TEST_F(PoseAndPasses, SkinnedMeshesWithoutSkinMorphAreLeftOut) {
    const fs::path fox = model("Fox/glTF-Binary/Fox.glb");
    REQUIRE_MODEL(fox);
    const Result normal = render(fox, "", "normal.png");
    ASSERT_EQ(normal.exitCode, 0) << normal.stderrText;
    EXPECT_GT(image("normal.png").unlikeCorner(), 0);
    const Result off = render(fox, "--disable-pass skin_morph --explain", "off.png");
    ASSERT_EQ(off.exitCode, 0) << off.stderrText;
    EXPECT_EQ(off.stderrText, "");
    EXPECT_NE(off.stdoutText.find("left out: the 1 deformed draws (skin_morph disabled"), std::string::npos) << off.stdoutText;
    EXPECT_EQ(off.stdoutText.find("hidden"), std::string::npos) << "not counted as hidden nodes:\n" << off.stdoutText;
    EXPECT_EQ(image("off.png").unlikeCorner(), 0) << "the Fox (its one skinned draw) is not drawn";
}

// Passes the image cannot be made without: one line naming the pass and what went with it.
TEST_F(PoseAndPasses, DisablingAPassTheImageNeedsIsOneLineNamingIt) {
    for (const auto& [pass, lost] : {std::pair{"forward", "tonemap, readback"}, std::pair{"tonemap", "readback"}}) {
        const Result r = run(std::string("render --validate --env none --width 32 --height 24 --shading-path forward --disable-pass ") +
                             pass + " --out '" + (mDir.path() / "x.png").string() + "'");
        EXPECT_EQ(r.exitCode, 2) << pass;
        EXPECT_EQ(r.stderrText, std::string("candela: error: nothing to capture: pass '") + pass +
                                    "' is disabled and the image cannot be made without it (lost with it: " + lost + ")\n");
        EXPECT_FALSE(fs::exists(mDir.path() / "x.png"));
    }
}

}  // namespace
