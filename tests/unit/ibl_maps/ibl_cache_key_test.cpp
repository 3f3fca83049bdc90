// The IBL cache key (ibl_maps/ibl_maps.h): the environment, every quality setting and the
// precompute shaders' code — a replaced (hot-reloaded) precompute shader is another key; a shader
// the precompute does not run is not part of it.
#include "ibl_maps/ibl_maps.h"
#include "shader/shader_library.h"

#include <gtest/gtest.h>

#include <vector>

namespace candela::ibl_maps {
namespace {

TEST(IblCacheKey, NamesTheEnvironmentTheQualityAndThePrecomputeShaders) {
    const ibl::IblQuality quality;
    const ibl::IblCacheKey key = iblCacheKey(42, quality);
    EXPECT_EQ(key.environmentHash, 42u);
    EXPECT_EQ(key.settings.rfind(quality.canonical() + " shaders=", 0), 0u) << key.settings;
    ibl::IblQuality finer = quality;
    finer.cubeSize *= 2;
    EXPECT_NE(iblCacheKey(42, finer).settings, key.settings);

    // A precompute shader replaced by other code: another key; back to the built-in one: the same.
    const std::span<const uint32_t> lut = shader::shaderSpirv("ibl_brdf_lut.comp");
    ASSERT_FALSE(lut.empty());
    std::vector<uint32_t> changed(lut.begin(), lut.end());
    changed.back() ^= 1u;
    shader::replaceShader("ibl_brdf_lut.comp", changed);
    EXPECT_NE(iblCacheKey(42, quality).settings, key.settings);
    shader::restoreBuiltinShaders();
    EXPECT_EQ(iblCacheKey(42, quality).settings, key.settings);
    // A shader the precompute does not run leaves the key alone.
    const std::span<const uint32_t> tonemap = shader::shaderSpirv("tonemap.frag");
    shader::replaceShader("tonemap.frag", std::vector<uint32_t>(tonemap.begin(), tonemap.end() - 1));
    EXPECT_EQ(iblCacheKey(42, quality).settings, key.settings);
    shader::restoreBuiltinShaders();
}

}  // namespace
}  // namespace candela::ibl_maps
