// The work of the default views, pinned: `candela render --report` on the default scene,
// DamagedHelmet, MetalRoughSpheresNoTextures and a batch of samples, and each scene's `work`
// counters (draws and triangles submitted, levels chosen, state changes, passes scheduled, texels
// decoded, meshes given levels of detail, environment precomputes, pipelines created) against
// tests/data/work-counters.json. A change that multiplies the work — as the framing change of
// issue 31 did, drawing 194,432 triangles where 25,872 had done, unnoticed — fails here with the
// counter that moved; the times stay in `candela bench` and the reports. After a deliberate change,
// CANDELA_APPROVE_WORK_COUNTERS=1 writes the file anew (say why in the commit).
#include "run_candela.h"
#include "temp_dir.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using candela::test::Result;
using candela::test::run;
using Json = nlohmann::json;

fs::path sample(const std::string& relative) { return candela::test::sharedAssets() / "models" / relative; }
const fs::path kPinned = fs::path(CANDELA_TEST_DATA) / "work-counters.json";

// One run of the render command and its scenes' work counters, by scene name.
Json workOf(const std::string& name, const std::string& args, const candela::test::TempDir& dir) {
    const fs::path report = dir.path() / (name + ".json");
    // The environment's maps and the levels of detail in folders of this test's own: other tests
    // of the process leave theirs in the process's cache folder, and whether a run computes the
    // maps or builds the levels is a counter.
    const Result r = run("render --validate --quiet " + args + " --ibl-cache '" + (dir.path() / "maps").string() +
                         "' --lod-cache '" + (dir.path() / "lod").string() + "' --report '" + report.string() + "'");
    EXPECT_EQ(r.exitCode, 0) << name << ": " << r.stderrText;
    EXPECT_EQ(r.stderrText, "") << name;
    std::ifstream in(report);
    Json out = Json::object();
    EXPECT_TRUE(in) << name << ": no report";
    if (!in) return out;
    const Json parsed = Json::parse(in);
    for (const Json& scene : parsed["scenes"]) out[scene["name"].get<std::string>()] = scene["work"];
    EXPECT_FALSE(out.empty()) << name << ": no scene in the report";
    return out;
}

// Every counter of `now` against `pinned`, one failure per counter that moved, naming it.
void compare(const std::string& run, const Json& pinned, const Json& now) {
    for (const auto& [scene, counters] : pinned.items()) {
        if (!now.contains(scene)) {
            ADD_FAILURE() << run << ": scene " << scene << " not rendered";
            continue;
        }
        for (const auto& [counter, value] : counters.items()) {
            const Json& moved = now[scene].contains(counter) ? now[scene][counter] : Json();
            if (moved == value) continue;
            std::string ratio;
            if (value.is_number() && moved.is_number() && value.get<double>() > 0)
                ratio = " (×" + std::to_string(moved.get<double>() / value.get<double>()) + ")";
            ADD_FAILURE() << run << ": " << scene << ": " << counter << " " << value.dump() << " → " << moved.dump() << ratio;
        }
    }
    for (const auto& [scene, counters] : now.items())
        if (!pinned.contains(scene)) ADD_FAILURE() << run << ": scene " << scene << " is not pinned";
}

TEST(WorkCounters, TheDefaultViewsDoThePinnedWork) {
    const std::vector<fs::path> batch = {sample("Duck/glTF-Binary/Duck.glb"), sample("Avocado/glTF/Avocado.gltf"),
                                         sample("CesiumMan/glTF-Binary/CesiumMan.glb"), sample("ToyCar/glTF/ToyCar.gltf"),
                                         sample("BoxTextured/glTF-Binary/BoxTextured.glb")};
    const fs::path helmet = sample("DamagedHelmet/glTF-Binary/DamagedHelmet.glb");
    const fs::path spheres = sample("MetalRoughSpheresNoTextures/glTF-Binary/MetalRoughSpheresNoTextures.glb");
    for (const fs::path& file : batch) if (!fs::exists(file)) GTEST_SKIP() << "shared asset missing: " << file;
    if (!fs::exists(helmet) || !fs::exists(spheres)) GTEST_SKIP() << "shared assets missing";
    candela::test::TempDir dir("candela_work_counters");  // with a fresh maps folder: the first run computes the sky's maps
    // In this order: the default scene computes the sky's maps, the later runs load them.
    Json now;
    now["default scene, 1280x720"] = workOf("default", "--out '" + (dir.path() / "default.png").string() + "'", dir);
    now["DamagedHelmet, 1280x720"] =
        workOf("helmet", "--scene '" + helmet.string() + "' --out '" + (dir.path() / "helmet.png").string() + "'", dir);
    now["MetalRoughSpheresNoTextures, 1280x720"] =
        workOf("spheres", "--scene '" + spheres.string() + "' --out '" + (dir.path() / "spheres.png").string() + "'", dir);
    std::string files;
    for (const fs::path& file : batch) files += " '" + file.string() + "'";
    now["a batch at 512x512"] =
        workOf("batch", files + " --width 512 --height 512 --out '" + (dir.path() / "{name}.png").string() + "'", dir);
    // In a batch, pipelines compiled ahead for the next scene while one draws may be counted in
    // either: pinned for the single scenes only.
    for (auto& [scene, counters] : now["a batch at 512x512"].items()) counters.erase("pipelinesCreated");

    if (const char* approve = std::getenv("CANDELA_APPROVE_WORK_COUNTERS"); approve && std::string(approve) == "1") {
        std::ofstream(kPinned) << now.dump(2) << "\n";
        GTEST_SKIP() << "wrote " << kPinned;
    }
    std::ifstream in(kPinned);
    ASSERT_TRUE(in) << kPinned << " missing: CANDELA_APPROVE_WORK_COUNTERS=1 writes it";
    const Json pinned = Json::parse(in);
    EXPECT_EQ(pinned.size(), now.size()) << "the runs pinned and run differ";
    for (const auto& [run, scenes] : pinned.items()) {
        EXPECT_FALSE(scenes.empty()) << run << ": nothing pinned";
        compare(run, scenes, now.contains(run) ? now[run] : Json::object());
    }
}

}  // namespace
