# Rendering from Python: the arrays (shape, type, ownership), the pixels the command line writes,
# the float formats, scenes from bytes, sequences, the GIL released while rendering.
import subprocess
import threading
import time

import numpy as np
import pytest

import candela
from conftest import CANDELA, shared_model


def read_pfm(path):
    """A PFM file's pixels as float32 rows top first (PFM stores them bottom first)."""
    data = path.read_bytes()
    header, _, rest = data.partition(b"\n")
    assert header == b"PF"
    size, _, rest = rest.partition(b"\n")
    width, height = map(int, size.split())
    scale, _, rest = rest.partition(b"\n")
    dtype = "<f4" if float(scale) < 0 else ">f4"
    return np.frombuffer(rest, dtype=dtype, count=width * height * 3).reshape(height, width, 3)[::-1]


def test_the_colour_is_an_array_numpy_owns(device, grid, sky):
    frame = device.render(grid, width=64, height=48, environment=sky)
    assert isinstance(frame, candela.Frame) and isinstance(frame, dict)
    color = frame["color"]
    assert color.shape == (48, 64, 4) and color.dtype == np.uint8
    assert color.flags["C_CONTIGUOUS"] and color.flags["OWNDATA"] and color.flags["WRITEABLE"]
    assert color[..., 3].max() == 255 and color[..., :3].std() > 10  # spheres over the sky, not one colour


@pytest.mark.skipif(not CANDELA, reason="CANDELA_EXECUTABLE not set")
def test_python_renders_what_the_command_line_renders(device, helmet, sky, tmp_path):
    subprocess.run([CANDELA, "render", "--scene", str(shared_model("DamagedHelmet")), "--width", "64", "--height", "48",
                    "--pipeline-cache", "off", "--out", str(tmp_path / "cli.pfm")], check=True, capture_output=True)
    cli = read_pfm(tmp_path / "cli.pfm")
    frame = device.render(helmet, width=64, height=48, environment=sky, dtype=np.float32)
    np.testing.assert_array_equal(frame["color"][..., :3], cli)


def test_float_formats_hold_the_same_values(device, grid):
    full = device.render(grid, width=32, height=24, dtype=np.float32)["color"]
    half = device.render(grid, width=32, height=24, dtype=np.float16)["color"]
    assert full.dtype == np.float32 and half.dtype == np.float16
    np.testing.assert_array_equal(half.astype(np.float32), full)  # the GPU wrote halves; float32 widens them
    assert full[..., 3].sum() > 0


def test_a_scene_from_bytes_is_the_files_scene(device, helmet):
    from_file = device.render(helmet, width=48, height=48)["color"]
    from_bytes = device.render(device.load_scene(shared_model("DamagedHelmet").read_bytes(), name="helmet.glb"),
                               width=48, height=48)["color"]
    np.testing.assert_array_equal(from_file, from_bytes)


def test_a_sequence_is_an_iterator_of_its_frames_one_at_a_time(device, grid):
    frames = device.render_sequence(grid, frames=3, turntable=90.0, width=40, height=30)
    assert len(frames) == 3
    first = next(frames)
    assert len(frames) == 2
    rest = list(frames)
    assert len(rest) == 2 and len(frames) == 0
    with pytest.raises(StopIteration):
        next(frames)
    # The camera turned 45° a frame about the scene's vertical axis, at one distance.
    eyes = [f.camera.camera_to_world[:3, 3] for f in [first, *rest]]
    assert not np.array_equal(first["color"], rest[0]["color"])
    radii = [np.linalg.norm(eye[[0, 2]]) for eye in eyes]
    assert max(radii) - min(radii) < 1e-4 * max(radii)


def test_sequences_play_animations_frame_by_frame(device):
    fox = device.load_scene(shared_model("Fox"))
    # One camera for both: framed by default, a sequence fits all its frames' poses, a still its own.
    camera = candela.Camera.orbit(0.0, 75.0, 300.0, target=(0.0, 40.0, 0.0))
    frames = [f["color"] for f in device.render_sequence(fox, frames=2, fps=2.0, animations="Run", camera=camera,
                                                         width=48, height=48)]
    still = device.render(fox, animations="Run", time=0.5, camera=camera, width=48, height=48)["color"]
    np.testing.assert_array_equal(frames[1], still)  # frame 1 at 1/fps s is the pose at 0.5 s
    assert not np.array_equal(frames[0], frames[1])
    # Framed by default, the camera holds still over the sequence.
    framed = [f.camera.camera_to_world for f in device.render_sequence(fox, frames=2, fps=2.0, animations="Run",
                                                                       width=48, height=48)]
    np.testing.assert_array_equal(framed[0], framed[1])


def test_the_gil_is_released_while_rendering(device, helmet):
    device.render(helmet, width=16, height=16)  # uploaded: the render below is the frame alone
    done = threading.Event()
    counted = 0

    def render():
        device.render(helmet, width=256, height=256, msaa=4)
        done.set()

    worker = threading.Thread(target=render)
    start = time.perf_counter()
    worker.start()
    while not done.is_set():
        counted += 1
        time.sleep(0.001)
    worker.join()
    elapsed = time.perf_counter() - start
    # Holding the GIL, the render would have let this loop run once or twice.
    assert counted > 10, f"{counted} loops in {elapsed:.2f} s"


def test_two_devices_render_on_two_threads(grid):
    results = {}

    def render(key):
        with candela.Device(validation=True, pipeline_cache="off") as own:
            results[key] = own.render(grid, width=32, height=32)["color"]
            assert own.validation_messages == 0

    threads = [threading.Thread(target=render, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    np.testing.assert_array_equal(results[0], results[1])


def test_a_new_scene_at_a_destroyed_ones_address_is_uploaded(device, sky):
    # Python frees a Scene as soon as its last reference goes, and the next one often takes its
    # memory: the device must not take it for the scene it uploaded (nor an environment likewise).
    fox = device.load_scene(shared_model("Fox"))
    device.render(fox, width=32, height=32, environment=candela.load_environment())
    del fox
    helmet_path = shared_model("DamagedHelmet")
    for _ in range(3):
        helmet = device.load_scene(helmet_path)
        drawn = device.render(helmet, width=32, height=32, msaa=4, environment=sky)["color"]
        del helmet
    with candela.Device(validation=True, pipeline_cache="off") as fresh:
        expected = fresh.render(fresh.load_scene(helmet_path), width=32, height=32, msaa=4, environment=sky)["color"]
        assert fresh.validation_messages == 0
    np.testing.assert_array_equal(drawn, expected)
    assert device.validation_messages == 0
