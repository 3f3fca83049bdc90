#pragma once
// Scenes and environments: read once on the host, then drawn by any Device.

#include "candela/version.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace candela {

// Reads a file a glTF refers to by a relative URI (a buffer or an image): its bytes, or nullopt
// when there is no such file. Called during Scene::fromMemory only.
using UriResolver = std::function<std::optional<std::vector<std::byte>>(const std::string& uri)>;

// A glTF 2.0 scene (.gltf or .glb, with the extensions docs/scenes.md lists), or the built-in
// sphere grid. Movable, not copyable; independent of any Device.
class CANDELA_API Scene {
public:
    // Reads `path` and the files it refers to (relative URIs, inside its folder). `sceneIndex`:
    // which of the file's scenes (unset: its default scene). Throws InputError naming the file and
    // the problem for anything missing or malformed.
    static Scene fromFile(const std::string& path, std::optional<uint32_t> sceneIndex = std::nullopt);
    // As fromFile, for a .gltf or .glb already in memory: `name` names it in messages; external
    // URIs are read through `resolver` (none: a URI is an InputError). Borrows `bytes` for the call.
    static Scene fromMemory(std::span<const std::byte> bytes, const std::string& name, const UriResolver& resolver = {},
                            std::optional<uint32_t> sceneIndex = std::nullopt);
    // The built-in grid of count × count spheres (metallic across, roughness down).
    static Scene sphereGrid(uint32_t count = 7);

    Scene(Scene&&) noexcept;
    Scene& operator=(Scene&&) noexcept;
    ~Scene();

    // The file's path or name ("sphere grid" for the built-in one).
    const std::string& name() const;
    // The KHR_materials_variants names, and the animations' names (an unnamed one: "animation N").
    std::vector<std::string> variants() const;
    std::vector<std::string> animations() const;
    // What was read but not as the file says (an unsupported optional extension, a repaired value).
    const std::vector<std::string>& warnings() const;

    struct Impl;

private:
    explicit Scene(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
    friend struct Access;
};

// An equirectangular environment that lights a scene (image-based lighting) and may be its
// background: a Radiance .hdr or OpenEXR .exr map, or the built-in procedural sky.
class CANDELA_API Environment {
public:
    // Reads `path` (.hdr or .exr, told apart by content). Throws InputError for anything missing,
    // truncated or malformed. NaN, infinite or negative texels are repaired, with a warning.
    static Environment fromFile(const std::string& path);
    // As fromFile, for a file's bytes in memory (`name` names it in messages). Borrows `bytes`.
    static Environment fromMemory(std::span<const std::byte> bytes, const std::string& name);
    // The built-in sky (`candela render`'s default environment).
    static Environment sky();

    Environment(Environment&&) noexcept;
    Environment& operator=(Environment&&) noexcept;
    ~Environment();

    const std::string& name() const;
    uint32_t width() const;
    uint32_t height() const;
    const std::vector<std::string>& warnings() const;

    struct Impl;

private:
    explicit Environment(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
    friend struct Access;
};

}  // namespace candela
