#pragma once
// The per-pixel outputs a frame can give besides its colour image (--outputs, RenderOptions::outputs,
// Python's outputs=; docs/outputs.md): their names, channels, and where the aov pass puts them (a
// target of shared/aov_targets.h and the channels within it). The one table the command line, the
// engine, the API and the file writers read.

#include "core/name_table.h"
#include "shared/aov_targets.h"

#include <array>
#include <initializer_list>
#include <iterator>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <utility>

namespace candela::options {

enum class PixelOutput : uint8_t {
    Color,              // the image (tone-mapped sRGB or linear float, as the frame's format says)
    Depth,              // view depth: distance along the view axis, world units (metres); +inf: nothing
    ClipDepth,          // the depth buffer: reverse Z, 1 at the near plane, 0 at the far one or nothing
    Normal,             // world-space unit shading normal (after the normal map); 0 where nothing
    BaseColor,          // linear base colour (factor × COLOR_0 × texture)
    Alpha,              // 1 for opaque and masked surfaces, the material's alpha for blended ones
    MetallicRoughness,  // metallic, perceptual roughness
    Emissive,           // emitted radiance (factor × strength × texture), linear
    NodeId,             // the glTF node (0xFFFFFFFF: none)
    MeshId,             // the glTF mesh
    PrimitiveId,        // the primitive's index within its mesh
    MaterialId,         // the glTF material (the default material: the file's material count)
    InstanceId,         // the EXT_mesh_gpu_instancing instance (0xFFFFFFFF: not instanced)
};

inline constexpr std::pair<PixelOutput, const char*> kPixelOutputNames[] = {
    {PixelOutput::Color, "color"},
    {PixelOutput::Depth, "depth"},
    {PixelOutput::ClipDepth, "clip_depth"},
    {PixelOutput::Normal, "normal"},
    {PixelOutput::BaseColor, "base_color"},
    {PixelOutput::Alpha, "alpha"},
    {PixelOutput::MetallicRoughness, "metallic_roughness"},
    {PixelOutput::Emissive, "emissive"},
    {PixelOutput::NodeId, "node_id"},
    {PixelOutput::MeshId, "mesh_id"},
    {PixelOutput::PrimitiveId, "primitive_id"},
    {PixelOutput::MaterialId, "material_id"},
    {PixelOutput::InstanceId, "instance_id"},
};
inline constexpr size_t kPixelOutputCount = std::size(kPixelOutputNames);

constexpr const char* pixelOutputName(PixelOutput value) { return nameOf(kPixelOutputNames, value); }

// A name that stands for several outputs: "ids" for the five IDs.
inline constexpr PixelOutput kIdOutputs[] = {PixelOutput::NodeId, PixelOutput::MeshId, PixelOutput::PrimitiveId,
                                             PixelOutput::MaterialId, PixelOutput::InstanceId};

// Where an output lies in the aov pass's targets, and what its channels are called (a file's
// channel names are "OUTPUT.CHANNEL", colour's R, G, B, A and depth's Z as OpenEXR names them).
struct PixelOutputLayout {
    uint32_t target = 0;        // CANDELA_AOV_* (Color: none)
    uint32_t firstChannel = 0;  // within the target
    uint32_t channels = 0;
    bool integer = false;       // 32-bit unsigned IDs; else 32-bit floats
    std::array<const char*, 4> channelNames{};
};

constexpr PixelOutputLayout pixelOutputLayout(PixelOutput output) {
    switch (output) {
        case PixelOutput::Color: return {0, 0, 4, false, {"R", "G", "B", "A"}};
        case PixelOutput::Depth: return {CANDELA_AOV_VIEW_DEPTH, 0, 1, false, {"Z"}};
        case PixelOutput::ClipDepth: return {CANDELA_AOV_CLIP_DEPTH, 0, 1, false, {"Z"}};
        case PixelOutput::Normal: return {CANDELA_AOV_NORMAL, 0, 3, false, {"X", "Y", "Z"}};
        case PixelOutput::BaseColor: return {CANDELA_AOV_BASE_COLOR, 0, 3, false, {"R", "G", "B"}};
        case PixelOutput::Alpha: return {CANDELA_AOV_BASE_COLOR, 3, 1, false, {"A"}};
        case PixelOutput::MetallicRoughness: return {CANDELA_AOV_METALLIC_ROUGHNESS, 0, 2, false, {"metallic", "roughness"}};
        case PixelOutput::Emissive: return {CANDELA_AOV_EMISSIVE, 0, 3, false, {"R", "G", "B"}};
        case PixelOutput::NodeId: return {CANDELA_AOV_IDS, 0, 1, true, {"id"}};
        case PixelOutput::MeshId: return {CANDELA_AOV_IDS, 1, 1, true, {"id"}};
        case PixelOutput::PrimitiveId: return {CANDELA_AOV_IDS, 2, 1, true, {"id"}};
        case PixelOutput::MaterialId: return {CANDELA_AOV_IDS, 3, 1, true, {"id"}};
        case PixelOutput::InstanceId: return {CANDELA_AOV_INSTANCE, 0, 1, true, {"id"}};
    }
    return {};
}

// A set of outputs, one bit per PixelOutput.
class PixelOutputs {
public:
    constexpr PixelOutputs() = default;
    constexpr PixelOutputs(std::initializer_list<PixelOutput> outputs) {
        for (PixelOutput o : outputs) add(o);
    }
    constexpr void add(PixelOutput o) { mBits |= 1u << uint32_t(o); }
    constexpr bool has(PixelOutput o) const { return (mBits >> uint32_t(o)) & 1u; }
    constexpr bool empty() const { return mBits == 0; }
    // Whether anything besides colour is asked for (the aov pass runs).
    constexpr bool beyondColor() const { return (mBits & ~1u) != 0; }
    // The aov pass's colour targets these outputs need (bit 1 << CANDELA_AOV_*, clip depth excluded).
    constexpr uint32_t aovTargets() const {
        uint32_t targets = 0;
        for (const auto& [o, name] : kPixelOutputNames)
            if (o != PixelOutput::Color && o != PixelOutput::ClipDepth && has(o)) targets |= 1u << pixelOutputLayout(o).target;
        return targets;
    }
    constexpr uint32_t bits() const { return mBits; }
    constexpr bool operator==(const PixelOutputs&) const = default;

private:
    uint32_t mBits = 0;
};

// The outputs of a list of names ("color", "depth", "ids", …); nullopt with `bad` set to the first
// name that is none.
inline std::optional<PixelOutputs> pixelOutputsNamed(std::span<const std::string_view> names, std::string_view* bad = nullptr) {
    PixelOutputs out;
    for (std::string_view name : names) {
        if (name == "ids") {
            for (PixelOutput o : kIdOutputs) out.add(o);
        } else if (const std::optional<PixelOutput> o = valueNamed(kPixelOutputNames, name)) {
            out.add(*o);
        } else {
            if (bad) *bad = name;
            return std::nullopt;
        }
    }
    return out;
}

// How the outputs besides colour are stored beside a .png or .pfm image (a .exr holds them all as
// its channels): one file each (--outputs-format, candela::OutputFileFormat).
enum class OutputFiles : uint8_t {
    Npy,  // NumPy arrays, float32 or uint32 (the values)
    Exr,  // OpenEXR, 32-bit float or uint channels (the values)
    Png,  // 8-bit pictures to look at (depth and IDs false-coloured), not data
};
inline constexpr std::pair<OutputFiles, const char*> kOutputFilesNames[] = {
    {OutputFiles::Npy, "npy"}, {OutputFiles::Exr, "exr"}, {OutputFiles::Png, "png"}};

}  // namespace candela::options
