#pragma once
// The debug views: what the shading (both paths) writes instead of the shaded colour — material
// inputs, the GGX terms toward the first punctual light, the light of each lobe, the layers'
// parameters — one per row of shared/shading_tables.h's CANDELA_DEBUG_VIEWS, which says what each
// shows (the shaders' CANDELA_DEBUG_* come from the same rows). Names only: no Vulkan (the
// command-line parser uses them).

#include "core/name_table.h"
#include "shared/shading_tables.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace candela::options {

#define CANDELA_DEBUG_VIEW_ENUMERATOR(NAME, Name, value, name, light) Name = value,
enum class DebugView : uint32_t { CANDELA_DEBUG_VIEWS(CANDELA_DEBUG_VIEW_ENUMERATOR) };
#undef CANDELA_DEBUG_VIEW_ENUMERATOR

// Each view with its name (the command line's and the viewer's) and whether it shows light.
struct DebugViewRow {
    DebugView view;
    const char* name;
    bool light;
};
#define CANDELA_DEBUG_VIEW_ROW(NAME, Name, value, name, light) {DebugView::Name, name, light},
inline constexpr DebugViewRow kDebugViews[] = {CANDELA_DEBUG_VIEWS(CANDELA_DEBUG_VIEW_ROW)};
#undef CANDELA_DEBUG_VIEW_ROW

// The same rows as the names table the command line and the lookups read.
#define CANDELA_DEBUG_VIEW_NAME(NAME, Name, value, name, light) std::pair<DebugView, const char*>{DebugView::Name, name},
inline constexpr std::pair<DebugView, const char*> kDebugViewNames[] = {CANDELA_DEBUG_VIEWS(CANDELA_DEBUG_VIEW_NAME)};
#undef CANDELA_DEBUG_VIEW_NAME

// The names above; nullopt for anything else.
constexpr std::optional<DebugView> parseDebugView(std::string_view name) { return valueNamed(kDebugViewNames, name); }

constexpr const char* debugViewName(DebugView view) { return nameOf(kDebugViewNames, view); }

// Every view but None, in menu order.
inline std::vector<DebugView> allDebugViews() {
    std::vector<DebugView> views;
    for (const DebugViewRow& row : kDebugViews)
        if (row.view != DebugView::None) views.push_back(row.view);
    return views;
}

// Data and material colours are shown as they are (linear tonemap, exposure 0); the diffuse,
// specular, clearcoat and sheen light go through the frame's tonemap like the full image.
inline bool debugViewIsLight(DebugView view) {
    for (const DebugViewRow& row : kDebugViews)
        if (row.view == view) return row.light;
    return false;
}

}  // namespace candela::options
