#pragma once
// What one image is: its size and pixel format, the camera, the tone mapping and exposure, the
// anti-aliasing, the shading path, the background, the animation time and the material variant.
// The defaults are `candela render`'s.

#include "candela/image.h"
#include "candela/version.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace candela {

// The camera: a glTF camera of the scene, or the orbit camera, which frames the scene's bounds
// unless a distance is given.
struct Camera {
    std::optional<uint32_t> gltfCamera;             // the scene's camera of this index
    std::optional<std::array<float, 3>> orbit;      // azimuth°, elevation°, distance (≤ 0: frame the bounds)
    std::optional<std::array<float, 3>> target;     // the point looked at [the bounds' centre]
    float fovYDegrees = 45.0f;                      // vertical field of view of the orbit camera
};

enum class Tonemap { PbrNeutral, Aces, Agx, Reinhard, Linear };
// Forward draws and shades each surface; Visibility writes a visibility buffer and shades it in
// compute; Auto picks per scene and device (docs/shading-paths.md). Images agree within ꟻLIP noise.
enum class ShadingPath { Auto, Forward, Visibility };

// What shows where the scene draws nothing.
struct Background {
    enum class Kind {
        Auto,         // the environment when there is one, else Color #262626
        Environment,  // the environment (without one: an InputError)
        Transparent,  // alpha 0
        Color,        // `srgb`
    } kind = Kind::Auto;
    std::array<float, 3> srgb{};  // sRGB-encoded, each in [0, 1]
};

struct RenderOptions {
    uint32_t width = 1280;
    uint32_t height = 720;
    PixelFormat format = PixelFormat::Rgba8Srgb;
    Camera camera;
    Tonemap tonemap = Tonemap::PbrNeutral;
    float exposureEv = 0.0f;              // stops
    std::optional<uint32_t> msaa;         // 1, 2, 4 or 8 samples; unset: the device's default
    ShadingPath shadingPath = ShadingPath::Auto;
    Background background;
    bool dither = false;                  // blue-noise dither before 8-bit quantization
    // The animations that pose the scene (names or indices as text; "all", "none"); empty: the
    // first animation. Each loops over its duration; `time` is in seconds.
    std::vector<std::string> animations;
    double time = 0.0;
    std::string variant;                  // a KHR_materials_variants name; "": the default materials
};

// An image sequence: frame i shows RenderOptions::time + i / fps; with turntableDegrees the orbit
// camera turns that far over the sequence, at one distance that frames every frame.
struct SequenceOptions {
    uint32_t frames = 1;
    double fps = 30.0;
    float turntableDegrees = 0.0f;
};

// Where a render stands, for a progress callback (Device::render).
struct RenderProgress {
    enum class Stage { Upload, Frame } stage = Stage::Upload;
    uint32_t frame = 0;       // the frame about to be drawn (Stage::Frame)
    uint32_t frameCount = 1;  // frames in this call
};

}  // namespace candela
