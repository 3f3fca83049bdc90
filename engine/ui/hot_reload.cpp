#include "ui/hot_reload.h"

#include "core/log.h"
#include "shader/builtin_shaders.h"
#include "shader/reflection.h"
#include "shader/shader_library.h"
#include "ui/glsl_compiler.h"

#include <algorithm>
#include <system_error>

namespace candela::ui {

namespace {

// The stage of built-in shader "NAME.STAGE".
VkShaderStageFlagBits stageOfName(std::string_view name) {
    return stageOfFile(std::filesystem::path(std::string(name) + ".glsl"));
}

// Why `replacement` cannot stand in for `original` without rebuilding descriptor sets, or "".
std::string layoutChange(const shader::ShaderReflection& original, const shader::ShaderReflection& replacement) {
    if (original.pushConstants.size != replacement.pushConstants.size)
        return "its push constants changed size (" + std::to_string(original.pushConstants.size) + " → " +
               std::to_string(replacement.pushConstants.size) + " bytes)";
    const auto key = [](const shader::DescriptorBinding& b) { return std::tuple(b.set, b.binding, b.type, b.count); };
    std::vector<std::tuple<uint32_t, uint32_t, VkDescriptorType, uint32_t>> a, b;
    for (const auto& binding : original.bindings) a.push_back(key(binding));
    for (const auto& binding : replacement.bindings) b.push_back(key(binding));
    if (a != b) return "its descriptor bindings changed";
    return {};
}

}  // namespace

std::filesystem::path findSourceShaders(const std::filesystem::path& start) {
    std::error_code ec;
    std::filesystem::path folder = start;
    for (int level = 0; level <= 4 && !folder.empty(); ++level) {
        if (std::filesystem::is_regular_file(folder / "shaders" / "builtin_shaders.txt", ec)) return folder / "shaders";
        if (folder == folder.parent_path()) break;
        folder = folder.parent_path();
    }
    return {};
}

std::filesystem::path sourceShadersOfExecutable() {
    std::error_code ec;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path() : findSourceShaders(executable.parent_path());
}

ShaderHotReload::ShaderHotReload(std::filesystem::path shaderDir) : mDir(std::move(shaderDir)) {
    std::error_code ec;
    mEnabled = !mDir.empty() && std::filesystem::is_directory(mDir, ec);
    if (mEnabled) scan(mTimes);
}

void ShaderHotReload::scan(std::map<std::filesystem::path, std::filesystem::file_time_type>& out) const {
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(mDir, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
        const std::filesystem::path& path = it->path();
        if (path.extension() != ".glsl" && path.extension() != ".h") continue;
        std::error_code timeError;
        const auto time = std::filesystem::last_write_time(path, timeError);
        if (!timeError) out[path] = time;
    }
}

bool ShaderHotReload::reload(const std::string& name, const std::filesystem::path& file) {
    const auto start = std::chrono::steady_clock::now();
    CompileResult result =
        compileGlsl(file, mDir, stageOfName(name), shader::builtinShaderSource(name).defines);
    const double compileMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    mIncludes[name] = std::set<std::filesystem::path>(result.includes.begin(), result.includes.end());
    if (!result.ok()) {
        mErrors[name] = result.errors;
        for (const std::string& e : result.errors) log::error("hot reload: " + e);
        return false;
    }
    try {
        const std::string change = layoutChange(shader::reflectSpirv(shader::builtinShader(name), name),
                                                shader::reflectSpirv(result.spirv, name));
        if (!change.empty()) {
            mErrors[name] = {file.string() + ": " + change + "; restart the viewer to use it"};
            log::error("hot reload: " + mErrors[name].front());
            return false;
        }
    } catch (const std::exception& e) {
        mErrors[name] = {file.string() + ": " + e.what()};
        return false;
    }
    shader::replaceShader(name, std::move(result.spirv));
    mErrors.erase(name);
    log::info("hot reload: " + name + " replaced (compiled in " + std::to_string(int(compileMs)) + " ms)");
    return true;
}

std::vector<std::string> ShaderHotReload::poll() {
    std::vector<std::string> replaced;
    if (!mEnabled) return replaced;
    std::map<std::filesystem::path, std::filesystem::file_time_type> now;
    scan(now);
    std::vector<std::filesystem::path> saved;
    auto newest = std::filesystem::file_time_type::min();
    for (const auto& [path, time] : now) {
        const auto it = mTimes.find(path);
        if (it != mTimes.end() && it->second == time) continue;
        saved.push_back(path);
        newest = std::max(newest, time);
    }
    mTimes = std::move(now);
    if (saved.empty()) return replaced;

    // The shaders to recompile: those compiled from a saved file (shaders/builtin_shaders.txt: a
    // program's variants share it), and those including a saved header (every shader when a
    // header's readers are not known yet). A shader whose source this folder lacks is left alone.
    std::map<std::string, std::filesystem::path> todo;
    for (const std::string_view builtin : shader::builtinShaderNames()) {
        const std::string name(builtin);
        const std::filesystem::path file = mDir / shader::builtinShaderSource(name).file;
        if (!mTimes.contains(file)) continue;
        const auto includes = mIncludes.find(name);
        for (const std::filesystem::path& path : saved) {
            std::error_code ec;
            const bool reads = std::filesystem::equivalent(file, path, ec) || includes == mIncludes.end() ||
                               std::any_of(includes->second.begin(), includes->second.end(), [&](const auto& header) {
                                   return std::filesystem::equivalent(header, path, ec);
                               });
            if (reads) todo[name] = file;
        }
    }
    for (const auto& [name, file] : todo)
        if (reload(name, file)) replaced.push_back(name);
    if (!replaced.empty())
        mLastSave = std::chrono::file_clock::to_sys(newest);
    return replaced;
}

std::vector<std::string> ShaderHotReload::errors() const {
    std::vector<std::string> all;
    for (const auto& [name, errors] : mErrors) all.insert(all.end(), errors.begin(), errors.end());
    return all;
}

}  // namespace candela::ui
