#include "shader/shader_library.h"

#include "shader/builtin_shaders.h"

#include <map>
#include <stdexcept>

namespace candela::shader {

namespace {

struct Replacement {
    std::vector<uint32_t> spirv;  // empty: the built-in one
    uint64_t generation = 0;
};

std::map<std::string, Replacement, std::less<>>& replacements() {
    static std::map<std::string, Replacement, std::less<>> table;
    return table;
}

}  // namespace

std::span<const uint32_t> shaderSpirv(std::string_view name) {
    const auto it = replacements().find(name);
    if (it != replacements().end() && !it->second.spirv.empty()) return it->second.spirv;
    return builtinShader(name);
}

uint64_t shaderGeneration(std::string_view name) {
    const auto it = replacements().find(name);
    return it == replacements().end() ? 0 : it->second.generation;
}

void replaceShader(std::string_view name, std::vector<uint32_t> spirv) {
    if (builtinShader(name).empty()) throw std::invalid_argument("no built-in shader named '" + std::string(name) + "'");
    Replacement& r = replacements()[std::string(name)];
    r.spirv = std::move(spirv);
    ++r.generation;
}

void restoreBuiltinShaders() {
    for (auto& [name, r] : replacements())
        if (!r.spirv.empty()) {
            r.spirv.clear();
            ++r.generation;
        }
}

}  // namespace candela::shader
