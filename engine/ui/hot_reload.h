#pragma once
// Shader hot reload for the viewer: watches a shaders/ folder (the sources of the built-in shaders,
// shaders/builtin_shaders.txt, and the headers they include). A saved source — for every built-in
// shader compiled from it, each with its defines — or a saved header, for every shader that
// includes it, is recompiled with glslang; if it compiles and keeps its descriptor and push-constant layout it
// replaces the built-in SPIR-V (shader/shader_library.h) and the pipelines using it are rebuilt at
// their next use. Otherwise its errors (FILE:LINE: message) are kept for the UI and the old
// pipelines keep running.

#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace candela::ui {

// The shaders/ folder of the source tree a build folder inside it belongs to: the first of
// `start` and its parents (four at most) that holds shaders/builtin_shaders.txt; empty when none
// does. From the executable's folder (build/release/app) it finds the tree's shaders/; an
// installed executable has none, and the viewer then reloads only from --shaders.
std::filesystem::path findSourceShaders(const std::filesystem::path& start);
// findSourceShaders from the running executable's folder (/proc/self/exe); empty if unknown.
std::filesystem::path sourceShadersOfExecutable();

class ShaderHotReload {
public:
    // `shaderDir`: the folder holding the built-in shaders' sources. Watches nothing if it does
    // not exist (an installed binary without its sources).
    explicit ShaderHotReload(std::filesystem::path shaderDir);

    // Looks for saved files (one stat per file) and handles them. Returns the shaders ("NAME.STAGE")
    // replaced by this call.
    std::vector<std::string> poll();

    bool enabled() const { return mEnabled; }
    const std::filesystem::path& folder() const { return mDir; }
    // The current compile errors of every shader that failed its last reload, in file order.
    std::vector<std::string> errors() const;
    // When the newest file handled by the last poll() that replaced something was saved.
    std::optional<std::chrono::system_clock::time_point> lastSave() const { return mLastSave; }

private:
    void scan(std::map<std::filesystem::path, std::filesystem::file_time_type>& out) const;
    bool reload(const std::string& name, const std::filesystem::path& file);

    std::filesystem::path mDir;
    bool mEnabled = false;
    std::map<std::filesystem::path, std::filesystem::file_time_type> mTimes;
    std::map<std::string, std::set<std::filesystem::path>> mIncludes;  // shader → headers it read
    std::map<std::string, std::vector<std::string>> mErrors;           // shader → errors
    std::optional<std::chrono::system_clock::time_point> mLastSave;
};

}  // namespace candela::ui
