#pragma once
// What the last frame's draws asked of the shading programs (Renderer::lastShading), for tests that
// assert its fields rather than the words --explain makes of them (passes::explainShading, whose
// words tests/unit/passes/shading_summary_test.cpp checks).

#include "render/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

namespace candela::test {

// The last frame's summary; an empty one, and a failure, when the last frame was no scene frame.
inline const passes::ShadingSummary& lastShading(const Renderer& renderer) {
    static const passes::ShadingSummary kNone;
    if (!renderer.lastShading()) ADD_FAILURE() << "the last frame was no scene frame";
    return renderer.lastShading() ? *renderer.lastShading() : kNone;
}

// The last frame's draws of shading variant `name` (ShadingVariant::name(), "pbr+ibl-cube", ...).
inline uint32_t variantDraws(const Renderer& renderer, const std::string& name) {
    const auto& variants = lastShading(renderer).variants;
    const auto it = variants.find(name);
    return it == variants.end() ? 0 : it->second;
}

// Whether a material of the last frame pays for the layers `bits` (shared/shading_tables.h's
// CANDELA_LAYER_* bits, scene::kLayer*): all of them, or, `exactly`, those and no other.
inline bool paysFor(const Renderer& renderer, uint32_t bits, bool exactly = false) {
    const auto& layered = lastShading(renderer).layered;
    return std::any_of(layered.begin(), layered.end(), [&](const passes::ShadingSummary::LayeredMaterial& m) {
        return exactly ? m.layers == bits : (m.layers & bits) == bits;
    });
}

}  // namespace candela::test
