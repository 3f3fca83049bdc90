#pragma once
// Images in host memory, as Device::render returns them, and writing them to files.

#include "candela/version.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <string>
#include <vector>

namespace candela {

enum class PixelFormat {
    Rgba8Srgb,    // 4 bytes a pixel: tone-mapped, sRGB-encoded, alpha = coverage (a PNG's pixels)
    Rgba16Float,  // 8 bytes: linear scene-referred light before tone mapping (IEEE half floats)
    Rgba32Float,  // 16 bytes: the same as 32-bit floats
};

// Bytes per pixel of `format`.
CANDELA_API std::size_t bytesPerPixel(PixelFormat format) noexcept;

// The camera an image was rendered with (docs/datasets.md, "Cameras").
struct CameraInfo {
    uint32_t width = 0, height = 0;  // the image's size in pixels
    // Camera to world, column-major (element [4·c + r] is row r of column c), in glTF's axes: the
    // camera looks down its −Z, +X right and +Y up in the image; metres.
    std::array<float, 16> cameraToWorld{};
    bool orthographic = false;  // a glTF orthographic camera: no intrinsics; see xmag, ymag
    // Perspective cameras: fx, fy, cx, cy in pixels, OpenCV's K = [fx 0 cx; 0 fy cy; 0 0 1] for an
    // image whose top-left corner is (0, 0), v down and pixel (i, j) centred at (i + ½, j + ½): a
    // point at (x, y, z) in the camera's axes lands at u = fx·x/(−z) + cx, v = −fy·y/(−z) + cy.
    std::array<float, 4> intrinsics{};
    float fovYDegrees = 0.0f;  // vertical field of view (perspective)
    float xmag = 0.0f, ymag = 0.0f;  // half width and height of an orthographic view (metres)
    float znear = 0.0f;  // near plane (metres)
    float zfar = std::numeric_limits<float>::infinity();  // far plane (infinity: none)
    // The projection the image was drawn with: Vulkan clip space (y down), reverse Z (depth 1 at
    // znear, 0 at zfar or infinity), column-major.
    std::array<float, 16> projection{};
};

// What a render gives per pixel (RenderOptions::outputs; docs/outputs.md): the colour image and
// the outputs besides it. Every output but colour describes the nearest surface at the pixel's
// centre (one sample per pixel, whatever the MSAA): exact at MSAA 1, never a blend at an edge.
enum class Output {
    Color,              // the image, in RenderOptions::format
    Depth,              // view depth: distance from the camera along its view axis (metres); +inf: nothing
    ClipDepth,          // the depth buffer: reverse Z, 1 at the near plane, 0 at the far one or nothing
    Normal,             // world-space unit shading normal, after the normal map (x, y, z); 0: nothing
    BaseColor,          // linear base colour (r, g, b): factor × COLOR_0 × texture
    Alpha,              // 1 for opaque and masked surfaces, the material's alpha for blended ones; 0: nothing
    MetallicRoughness,  // metallic, perceptual roughness
    Emissive,           // emitted radiance factor × strength × texture (r, g, b), linear
    NodeId,             // the glTF node index; NoId: none (nothing drawn, or a built-in scene)
    MeshId,             // the glTF mesh index
    PrimitiveId,        // the primitive's index within its mesh
    MaterialId,         // the glTF material index (a primitive without one: the file's material count)
    InstanceId,         // the EXT_mesh_gpu_instancing instance index; NoId: not instanced
};
// The ID outputs' value where there is none.
inline constexpr uint32_t NoId = 0xFFFFFFFFu;
// An output's name as --outputs, Python and files spell it ("depth", "node_id").
CANDELA_API const char* outputName(Output output) noexcept;
// The outputs a name stands for: one, or the five IDs for "ids"; empty for an unknown name.
CANDELA_API std::vector<Output> outputsNamed(std::string_view name);
// Every output, in order.
CANDELA_API std::vector<Output> allOutputs();
// The names of an output's channels ("X", "Y", "Z" for the normal; "Z" for depth).
CANDELA_API std::vector<std::string> outputChannels(Output output);

// One output besides colour: rows top first, width × channels values a row, 32-bit floats or, for
// the IDs, 32-bit unsigned integers.
struct OutputImage {
    Output output = Output::Depth;
    uint32_t width = 0, height = 0, channels = 0;
    std::vector<float> values;  // the float outputs
    std::vector<uint32_t> ids;  // the ID outputs
};

// An image in host memory: rows top first, each width × bytesPerPixel(format) bytes, no padding.
struct Image {
    uint32_t width = 0;
    uint32_t height = 0;
    PixelFormat format = PixelFormat::Rgba8Srgb;
    std::vector<std::byte> pixels;  // empty when RenderOptions::outputs left colour out
    CameraInfo camera;  // the camera it was rendered with (Device::render, renderSequence)
    std::vector<OutputImage> outputs;  // RenderOptions::outputs besides colour, in Output order
};

// How writeImage stores the outputs besides colour beside a .png or .pfm: one file each.
enum class OutputFileFormat {
    Npy,  // NumPy arrays, H×W or H×W×C, float32 or uint32 (the values themselves)
    Exr,  // OpenEXR, 32-bit float or uint channels (the values themselves)
    Png,  // 8-bit pictures to look at (depth and IDs false-coloured), not data
};

// The files writeImage writes for an image with `outputs` at `path`: `path` for colour (and, for a
// .exr, every other output in that one file); beside a .png or .pfm, "STEM.OUTPUT.EXT" in the same
// folder for each other output. Throws InputError for an unknown extension.
CANDELA_API std::vector<std::string> outputFiles(const std::string& path, const std::vector<Output>& outputs,
                                                 OutputFileFormat format = OutputFileFormat::Npy);

// Writes `image` to `path` as `candela render --out` does: .png from Rgba8Srgb; .exr (half-float
// RGBA) or .pfm (float RGB) from either float format. Its other outputs go where outputFiles says:
// into the .exr as named channels (colour R, G, B, A; depth Z; "normal.X", "node_id.id", …, 32-bit
// float or uint), else one `outputFormat` file each. Throws InputError naming the file for another
// extension, a pixel format the file type does not hold, or a file that cannot be written.
CANDELA_API void writeImage(const std::string& path, const Image& image, OutputFileFormat outputFormat = OutputFileFormat::Npy);

}  // namespace candela
