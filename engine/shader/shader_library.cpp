#include "shader/shader_library.h"

#include "shader/builtin_shaders.h"

#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace candela::shader {

namespace {

struct Replacement {
    const std::vector<uint32_t>* spirv = nullptr;  // null: the built-in one
    uint64_t generation = 0;
};

// Every replacement's SPIR-V, kept to the end (a hot-reload session makes a few KiB per edit), so
// that spans handed out never dangle.
struct Library {
    std::mutex mutex;
    std::map<std::string, Replacement, std::less<>> replacements;
    std::vector<std::unique_ptr<const std::vector<uint32_t>>> kept;
};

Library& library() {
    static Library table;
    return table;
}

}  // namespace

ShaderVersion currentShader(std::string_view name) {
    Library& lib = library();
    std::lock_guard lock(lib.mutex);
    const auto it = lib.replacements.find(name);
    if (it == lib.replacements.end()) return {builtinShader(name), 0};
    return {it->second.spirv ? std::span<const uint32_t>(*it->second.spirv) : builtinShader(name), it->second.generation};
}

std::span<const uint32_t> shaderSpirv(std::string_view name) { return currentShader(name).spirv; }

uint64_t shaderGeneration(std::string_view name) { return currentShader(name).generation; }

void replaceShader(std::string_view name, std::vector<uint32_t> spirv) {
    if (builtinShader(name).empty()) throw std::invalid_argument("no built-in shader named '" + std::string(name) + "'");
    Library& lib = library();
    std::lock_guard lock(lib.mutex);
    Replacement& r = lib.replacements[std::string(name)];
    r.spirv = spirv.empty() ? nullptr : lib.kept.emplace_back(std::make_unique<const std::vector<uint32_t>>(std::move(spirv))).get();
    ++r.generation;
}

void restoreBuiltinShaders() {
    Library& lib = library();
    std::lock_guard lock(lib.mutex);
    for (auto& [name, r] : lib.replacements)
        if (r.spirv) {
            r.spirv = nullptr;
            ++r.generation;
        }
}

}  // namespace candela::shader
