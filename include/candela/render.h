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

// The camera: a glTF camera of the scene; a camera placed by its camera-to-world matrix; or the
// orbit camera, which frames what the scene shows unless a distance is given (docs/scenes.md,
// "Framing": the target, the distance and the field of view it chooses).
struct Camera {
    std::optional<uint32_t> gltfCamera;             // the scene's camera of this index
    std::optional<std::array<float, 3>> orbit;      // azimuth°, polar angle° from +Y, distance (≤ 0: frame the bounds)
    std::optional<std::array<float, 3>> target;     // the point looked at [the bounds' centre]
    // Vertical field of view of the orbit or placed camera; none: framing's for the orbit camera that
    // frames the scene, else 45°.
    std::optional<float> fovYDegrees;
    // Camera to world, column-major, in glTF's axes (the camera looks down its −Z, +Y up): overrides
    // orbit and target. lookAt() makes one. Its near plane is 1/1000 of its distance to the scene's centre.
    std::optional<std::array<float, 16>> cameraToWorld;
    // Pinhole intrinsics fx, fy, cx, cy in pixels of the rendered image (CameraInfo::intrinsics
    // says the convention): override fovYDegrees. Not with gltfCamera. With the orbit camera the
    // distance framing chooses does not change (as with fovYDegrees).
    std::optional<std::array<float, 4>> intrinsics;
};

// A camera at `eye` looking at `target`, `up` pointing up in the image (up must not be parallel to
// the line of sight). Throws InputError when eye and target coincide or up is parallel.
CANDELA_API Camera lookAt(const std::array<float, 3>& eye, const std::array<float, 3>& target,
                          const std::array<float, 3>& up = {0.0f, 1.0f, 0.0f});

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
    float environmentRotationDegrees = 0.0f;  // turns the environment about +Y (from +X towards +Z)
    // What to render per pixel (Image::pixels for Output::Color, Image::outputs for the rest).
    // Without Color the passes that make the image are culled and Image::pixels is empty.
    std::vector<Output> outputs{Output::Color};
};

// An image sequence: frame i shows RenderOptions::time + i / fps; with turntableDegrees the orbit
// camera turns that far over the sequence, at one distance that frames every frame.
struct SequenceOptions {
    uint32_t frames = 1;
    double fps = 30.0;
    float turntableDegrees = 0.0f;
    // Views of one pose instead: when not empty, frame i looks from the orbit direction views[i]
    // (azimuth°, polar angle°, as Camera::orbit), all at the one distance that frames every view
    // (or Camera::orbit's distance when given), at RenderOptions::time; frames, fps and
    // turntableDegrees are then not used. sphereViews() and ringViews() make them.
    std::vector<std::array<float, 2>> views;
    // Jittered lighting: frame i's environment turned by a further angle in [0°, 360°) drawn from
    // (seed, i) — the same for the same seed on every machine. Unset: no jitter.
    std::optional<uint64_t> lightingSeed;
};

// The number of images `sequence` makes: views.size() when views are given, else frames.
inline uint32_t frameCount(const SequenceOptions& sequence) {
    return sequence.views.empty() ? sequence.frames : uint32_t(sequence.views.size());
}

// `count` directions spread evenly over the sphere (a Fibonacci lattice: polar angles at equal
// steps of cos φ, azimuths 137.5° apart), from the top down.
CANDELA_API std::vector<std::array<float, 2>> sphereViews(uint32_t count);
// `count` directions on a ring `elevationDegrees` above the horizon, azimuths 360° / count apart
// from 0 (+Z).
CANDELA_API std::vector<std::array<float, 2>> ringViews(uint32_t count, float elevationDegrees);

// Where a render stands, for a progress callback (Device::render).
struct RenderProgress {
    enum class Stage { Upload, Frame } stage = Stage::Upload;
    uint32_t frame = 0;       // the frame about to be drawn (Stage::Frame)
    uint32_t frameCount = 1;  // frames in this call
};

}  // namespace candela
