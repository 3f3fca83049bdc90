#pragma once
// The viewer's panel sections and their names: the one table that the viewer, the command
// line (--panels) and the tests read. Names only: no Vulkan, no ImGui.

#include "core/name_table.h"

#include <cstdint>
#include <optional>
#include <set>
#include <string_view>
#include <utility>

namespace candela::options {

enum class Panel : uint8_t { Graph, Parameters, Materials, Environment, Camera, Animation, Debug, Stats };

// In the order the viewer shows them.
inline constexpr std::pair<Panel, const char*> kPanelNames[] = {
    {Panel::Graph, "graph"},   {Panel::Parameters, "parameters"}, {Panel::Materials, "materials"},
    {Panel::Environment, "environment"}, {Panel::Camera, "camera"}, {Panel::Animation, "animation"},
    {Panel::Debug, "debug"},   {Panel::Stats, "stats"}};

// The panels open at start unless the command line says otherwise.
inline const std::set<Panel> kPanelsOpenByDefault = {Panel::Graph, Panel::Parameters, Panel::Stats};

// The panel named `name` in kPanelNames; nullopt for anything else.
constexpr std::optional<Panel> parsePanel(std::string_view name) { return valueNamed(kPanelNames, name); }

}  // namespace candela::options
