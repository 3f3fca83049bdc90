#pragma once
// The shading programs' storage blocks that hold the scene's data, each a runtime array of one
// shading:: type (shared/scene_data.h), named once for C++: the descriptor writers bind them by this
// name and the parameter registry edits their elements (e.g. "Lights[2]") through it.

#include "shader/reflection.h"
#include "shared/scene_data.h"

#include <span>
#include <string_view>

namespace candela::passes {

template <class T>
struct SceneBlock;
template <>
struct SceneBlock<shading::LightData> {
    static constexpr std::string_view name = "Lights";  // set 0, binding 0
};
template <>
struct SceneBlock<shading::DrawData> {
    static constexpr std::string_view name = "Draws";  // set 0, binding 1
};
template <>
struct SceneBlock<shading::MaterialData> {
    static constexpr std::string_view name = "Materials";  // set 0, binding 2
};
template <>
struct SceneBlock<shading::MaterialLayerData> {
    static constexpr std::string_view name = "MaterialLayers";  // set 1, binding 5 (layered program)
};

// The reflected members of one element of T's block in `reflection`; empty when the program has
// no such block.
template <class T>
std::span<const shader::BlockMember> sceneBlockElement(const shader::ShaderReflection& reflection) {
    for (const shader::DescriptorBinding& b : reflection.bindings)
        if (b.name == SceneBlock<T>::name && b.members.size() == 1) return b.members[0].elementMembers;
    return {};
}

}  // namespace candela::passes
