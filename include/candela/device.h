#pragma once
// A Vulkan 1.3 device and a renderer on it: renders Scenes lit by Environments into host memory.
//
// Threads: a Device is used from one thread at a time (cancel() excepted); several Devices may
// render at once on different threads. A Scene or Environment may be read by several Devices at
// once, but a render with RenderOptions::variant selects that variant in the Scene: do not render
// one Scene with different variants on two threads at once.
// Lifetime: a Device holds no reference to a Scene or Environment after a call returns, but keeps
// what it uploaded of the last ones (so that the next image of the same scene starts at once)
// until another is drawn or release() is called.

#include "candela/errors.h"
#include "candela/render.h"
#include "candela/scene.h"
#include "candela/version.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace candela {

struct DeviceOptions {
    // Which device: "" the one the CANDELA_DEVICE variable selects, else the best one (a discrete
    // GPU before an integrated one before a CPU driver); else an index or a case-insensitive part
    // of its name (as `candela info` lists them). A selector containing "swiftshader" adds the
    // SwiftShader driver of Debian's chromium package (docs/devices.md).
    std::string device;
    // Narrows what Candela uses of the device to a profile: "native" (all of it), "minimum",
    // "desktop" or "apple" (docs/device-layer.md); "": the CANDELA_DEVICE_PROFILE variable, else native.
    std::string profile;
    // The Khronos validation layer with synchronization validation (slow; for testing). Its
    // messages are counted (Device::validationMessages) and printed to stderr.
    bool validation = false;
    // The folder of the on-disk pipeline cache: "" the user's cache folder ($XDG_CACHE_HOME/candela),
    // "off" none.
    std::string pipelineCache;
    // The folder of the on-disk cache of environments' precomputed maps: "" the user's cache
    // folder's ($XDG_CACHE_HOME/candela/ibl), "off" none (computed for every new environment).
    std::string iblCache;
    // The folder of the on-disk cache of meshes' levels of detail, and of the frames drawn without
    // them (a render builds them once they pay over every run: docs/geometry.md): "" the user's
    // cache folder's ($XDG_CACHE_HOME/candela/lod), "off" none (this process's frames alone count).
    std::string lodCache;
    // Caps the device memory used (MiB; 0: the device's own limit). Beyond it: OutOfMemoryError.
    uint32_t memoryBudgetMib = 0;
};

// Called before each stage of a render; returning false cancels it (the call throws CancelledError).
using ProgressCallback = std::function<bool(const RenderProgress& progress)>;
// Receives frame `index` of a sequence, valid during the call.
using FrameCallback = std::function<void(uint32_t index, const Image& image)>;

class CANDELA_API Device {
public:
    // Starts the device. Throws DeviceError when there is no suitable device, InputError for a bad
    // `device` or `profile` choice.
    explicit Device(const DeviceOptions& options = {});
    Device(Device&&) noexcept;
    Device& operator=(Device&&) noexcept;
    ~Device();

    // The device's name (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)").
    const std::string& name() const;

    // Renders one image of `scene` lit by `environment` (null: the scene's lights, or a default key
    // and fill light). Waits for the GPU. Throws InputError for options the scene or device cannot
    // meet (a size of 0 or beyond the device's limit, a glTF camera or variant or animation that
    // does not exist), CancelledError, DeviceLostError, OutOfMemoryError.
    Image render(const Scene& scene, const RenderOptions& options, const Environment* environment = nullptr,
                 const ProgressCallback& progress = {});
    // As render(), into `pixels`: options.height rows of `rowBytes` bytes each (at least
    // options.width × bytesPerPixel(options.format)), top row first; returns the camera. Precondition:
    // `pixels` holds them all.
    CameraInfo renderInto(void* pixels, std::size_t rowBytes, const Scene& scene, const RenderOptions& options,
                    const Environment* environment = nullptr, const ProgressCallback& progress = {});
    // Renders `sequence.frames` images, handing each to `onFrame` as it is read back.
    void renderSequence(const Scene& scene, const RenderOptions& options, const SequenceOptions& sequence,
                        const FrameCallback& onFrame, const Environment* environment = nullptr,
                        const ProgressCallback& progress = {});

    // Asks the render in progress (on another thread) to stop at its next stage, where it throws
    // CancelledError. Safe from any thread; a later render starts afresh.
    void cancel() noexcept;
    // Frees the device memory of the last scene drawn (the environment's maps and the pipelines stay).
    void release();
    // Validation messages so far (DeviceOptions::validation); 0 without validation.
    uint32_t validationMessages() const;

    struct Impl;

private:
    explicit Device(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
    friend struct Access;
};

// The options of frame `index` of `sequence` (index < frameCount(sequence)): RenderOptions::time
// advanced by index / fps, or for views the orbit camera's direction views[index]; for a turntable
// the orbit camera turned; the orbit's one distance that frames every frame; the environment's
// jittered rotation. Device::renderSequence renders exactly these; with them a caller renders the
// frames one at a time. Throws InputError for a sequence of 0 frames, fps ≤ 0, an index beyond it,
// or views of a glTF or placed camera.
CANDELA_API RenderOptions sequenceFrame(const Scene& scene, const RenderOptions& options,
                                        const SequenceOptions& sequence, uint32_t index);

}  // namespace candela
