#pragma once
// ImGui widgets for the members of a reflected parameter block, chosen by type and annotation:
// /*Color*/ vec3/vec4 → colour editor, /*Range(MIN, MAX)*/ → slider, other floats → drag, ints →
// drag, bools → checkbox; /*Ignore*/ members are never shown (ParameterRegistry drops them).
// Shared by the shader-parameter panel and the material inspector.

#include "shader/parameter_registry.h"

#include <span>
#include <string_view>

namespace candela::ui {

// Draws one widget per member of `block`; an edit sets the value in `registry` (effective next
// frame). A member with a user value gets a reset button; a label too long for the room right of
// the widget (PushItemWidth) is put above it. Members named in `unseen` (full names,
// "params.background") are drawn disabled: the frame does not show their effect. Returns true if
// anything was edited.
bool drawParameterBlock(shader::ParameterRegistry& registry, const shader::ParameterRegistry::Block& block,
                        std::span<const std::string_view> unseen = {});

}  // namespace candela::ui
