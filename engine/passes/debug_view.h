#pragma once
// The forward pass's debug views: what it writes instead of the shaded colour (CANDELA_DEBUG_* in
// shared/scene_data.h). Material inputs: base colour, normals before and after the normal map,
// roughness, metallic, occlusion, emissive. The GGX terms toward the first punctual light: D
// (relative to its peak), G (Smith) and F (Schlick). The diffuse and the specular light alone
// (punctual + environment). Material layers (docs/materials.md): the light the clearcoat reflects
// and the coat's normal (black where there is no coat), the light the sheen reflects, the
// anisotropy direction (scaled by its strength), the transmission's throughput (the fraction of the
// light behind the surface that comes through, per channel), the thin film's thickness and the
// Fresnel it gives. Names only: no Vulkan (the command-line
// parser uses them).

#include "core/name_table.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace candela::passes {

enum class DebugView : uint32_t {
    None = 0, BaseColor, GeometricNormal, MappedNormal, Roughness, Metallic, Occlusion, Emissive, D, G, F, Diffuse, Specular,
    Clearcoat, ClearcoatNormal, Sheen, Anisotropy, Transmission, IridescenceThickness, IridescenceFresnel
};

inline constexpr std::pair<DebugView, const char*> kDebugViewNames[] = {
    {DebugView::None, "none"},
    {DebugView::BaseColor, "base-color"},
    {DebugView::GeometricNormal, "geometric-normal"},
    {DebugView::MappedNormal, "mapped-normal"},
    {DebugView::Roughness, "roughness"},
    {DebugView::Metallic, "metallic"},
    {DebugView::Occlusion, "occlusion"},
    {DebugView::Emissive, "emissive"},
    {DebugView::D, "d"},
    {DebugView::G, "g"},
    {DebugView::F, "f"},
    {DebugView::Diffuse, "diffuse"},
    {DebugView::Specular, "specular"},
    {DebugView::Clearcoat, "clearcoat"},
    {DebugView::ClearcoatNormal, "clearcoat-normal"},
    {DebugView::Sheen, "sheen"},
    {DebugView::Anisotropy, "anisotropy-direction"},
    {DebugView::Transmission, "transmission"},
    {DebugView::IridescenceThickness, "iridescence-thickness"},
    {DebugView::IridescenceFresnel, "iridescence-fresnel"}};

// The names above; nullopt for anything else.
constexpr std::optional<DebugView> parseDebugView(std::string_view name) { return valueNamed(kDebugViewNames, name); }

constexpr const char* debugViewName(DebugView view) { return nameOf(kDebugViewNames, view); }

// Every view but None, in menu order.
inline std::vector<DebugView> allDebugViews() {
    std::vector<DebugView> views;
    for (const auto& [view, text] : kDebugViewNames)
        if (view != DebugView::None) views.push_back(view);
    return views;
}

// Data and material colours are shown as they are (linear tonemap, exposure 0); the diffuse,
// specular and clearcoat light go through the frame's tonemap like the full image.
inline bool debugViewIsLight(DebugView view) {
    return view == DebugView::Diffuse || view == DebugView::Specular || view == DebugView::Clearcoat ||
           view == DebugView::Sheen;
}

}  // namespace candela::passes
