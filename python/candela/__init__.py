"""Candela from Python: physically based glTF 2.0 rendering on Vulkan into NumPy arrays.

    import candela
    with candela.Device() as device:
        scene = device.load_scene("DamagedHelmet.glb")
        frame = device.render(scene, width=512, height=512, environment=device.load_environment())
        frame["color"]        # numpy.ndarray, 512 x 512 x 4, uint8 sRGB (alpha: coverage)
        frame.camera.K        # the intrinsics it was rendered with
        device.render(scene, outputs=["color", "depth", "normal", "ids"])  # per-pixel outputs besides

docs/python.md describes every call; the C++ API it binds is include/candela/.
"""

from ._candela import (
    Camera,
    CameraInfo,
    CancelledError,
    Device,
    DeviceError,
    DeviceLostError,
    Environment,
    Error,
    InputError,
    InternalFailure,
    OutOfMemoryError,
    NO_ID,
    OUTPUTS,
    Scene,
    SequenceIterator,
    __version__,
    load_environment,
    load_scene,
    ring_views,
    sphere_views,
    transforms_json,
    write_image,
)


class Frame(dict):
    """One rendered image: output name -> NumPy array (height x width x channels, or height x width
    for one channel; C-contiguous, owned by NumPy; docs/outputs.md); `camera`, the CameraInfo it was rendered with, and `environment_rotation`,
    the environment's turn in degrees (jittered per view with lighting_seed)."""

    camera: CameraInfo
    environment_rotation: float

    def __repr__(self):
        shapes = ", ".join(f"{name}: {array.dtype}{list(array.shape)}" for name, array in self.items())
        return f"Frame({shapes}; {self.camera!r})"


__all__ = [
    "Camera", "CameraInfo", "CancelledError", "Device", "DeviceError", "DeviceLostError", "Environment", "Error",
    "Frame", "InputError", "InternalFailure", "NO_ID", "OUTPUTS", "OutOfMemoryError", "Scene", "SequenceIterator", "__version__",
    "load_environment", "load_scene", "ring_views", "sphere_views", "transforms_json", "write_image",
]
