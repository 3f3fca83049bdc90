# Views and their cameras from Python: sphere and ring views at one distance, jittered lighting,
# and transforms.json equal to the one `candela render --views` writes for the same views.
import json
import subprocess

import numpy as np
import pytest

import candela
from conftest import CANDELA, shared_model
from test_render import read_pfm


def test_views_look_from_their_directions_at_one_distance(device, grid, sky):
    views = candela.sphere_views(6)
    frames = list(device.render_sequence(grid, views=views, lighting_seed=5, width=40, height=30, environment=sky))
    assert len(frames) == 6
    radii = []
    for (azimuth, polar), frame in zip(views, frames):
        eye = frame.camera.camera_to_world[:3, 3]
        a, p = np.radians(azimuth), np.radians(polar)
        direction = np.array([np.sin(p) * np.sin(a), np.cos(p), np.sin(p) * np.cos(a)])
        assert np.dot(eye / np.linalg.norm(eye), direction) > 0.99999
        radii.append(np.linalg.norm(eye))
    assert max(radii) - min(radii) < 1e-4 * max(radii)
    rotations = [f.environment_rotation for f in frames]
    assert len(set(rotations)) == 6 and all(0 <= r < 360 for r in rotations)
    again = [f.environment_rotation for f in device.render_sequence(grid, views=views, lighting_seed=5, width=8, height=8)]
    assert again == rotations  # the same seed, the same lighting
    ring = candela.ring_views(4, 30.0)
    assert ring == [(0.0, 60.0), (90.0, 60.0), (180.0, 60.0), (270.0, 60.0)]


@pytest.mark.skipif(not CANDELA, reason="CANDELA_EXECUTABLE not set")
def test_transforms_json_and_images_equal_the_command_lines(device, helmet, sky, tmp_path):
    subprocess.run([CANDELA, "render", "--scene", str(shared_model("DamagedHelmet")), "--views", "3", "--light-seed", "9", "--width", "48",
                    "--height", "40", "--pipeline-cache", "off", "--out", str(tmp_path / "views/%03d.pfm")],
                   check=True, capture_output=True)
    cli = (tmp_path / "views" / "transforms.json").read_text()
    frames = list(device.render_sequence(helmet, views=candela.sphere_views(3), lighting_seed=9, width=48, height=40,
                                         environment=sky, dtype=np.float32))
    assert candela.transforms_json([(f"{i:03d}.pfm", f) for i, f in enumerate(frames)]) == cli
    for i, frame in enumerate(frames):
        np.testing.assert_array_equal(frame["color"][..., :3], read_pfm(tmp_path / "views" / f"{i:03d}.pfm"))
    parsed = json.loads(cli)
    assert [f["file_path"] for f in parsed["frames"]] == ["000.pfm", "001.pfm", "002.pfm"]
    np.testing.assert_allclose(np.array(parsed["frames"][1]["transform_matrix"]), frames[1].camera.camera_to_world, rtol=1e-6)
    assert parsed["fl_x"] == pytest.approx(frames[0].camera.K[0, 0])
