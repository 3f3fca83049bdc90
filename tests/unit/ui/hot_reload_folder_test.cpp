// Where the viewer's hot reload looks by default (ui/hot_reload.h): the shaders/ folder of the
// source tree a build folder sits in, found upwards from the executable's folder; none elsewhere.
#include "temp_dir.h"
#include "ui/hot_reload.h"

#include <gtest/gtest.h>

#include <fstream>

namespace candela::ui {
namespace {

TEST(HotReloadFolder, FoundFromABuildFolderInsideTheTree) {
    test::TempDir dir("candela_hot_reload_folder");
    const std::filesystem::path tree = dir.path() / "tree";
    std::filesystem::create_directories(tree / "shaders");
    std::ofstream(tree / "shaders" / "builtin_shaders.txt") << "# a table\n";
    const std::filesystem::path app = tree / "build" / "release" / "app";
    std::filesystem::create_directories(app);
    EXPECT_EQ(findSourceShaders(app), tree / "shaders");
    EXPECT_EQ(findSourceShaders(tree), tree / "shaders");
}

TEST(HotReloadFolder, NoneOutsideATreeOrTooFarBelowIt) {
    test::TempDir dir("candela_hot_reload_folder");
    const std::filesystem::path bin = dir.path() / "opt" / "x" / "bin";
    std::filesystem::create_directories(bin);
    EXPECT_EQ(findSourceShaders(bin), std::filesystem::path());
    // A shaders/ folder without the table is not the tree's.
    std::filesystem::create_directories(dir.path() / "opt" / "shaders");
    EXPECT_EQ(findSourceShaders(bin), std::filesystem::path());
    // Five levels below the tree: not searched.
    std::filesystem::create_directories(dir.path() / "shaders");
    std::ofstream(dir.path() / "shaders" / "builtin_shaders.txt") << "# a table\n";
    const std::filesystem::path deep = dir.path() / "a" / "b" / "c" / "d" / "e";
    std::filesystem::create_directories(deep);
    EXPECT_EQ(findSourceShaders(deep), std::filesystem::path());
    EXPECT_EQ(findSourceShaders(deep.parent_path()), dir.path() / "shaders");
}

}  // namespace
}  // namespace candela::ui
