# Cameras from Python: the camera every frame reports (K, camera to world, field of view, near/far)
# and the cameras that reproduce it: look-at, a camera-to-world matrix, intrinsics K, a glTF camera.
import math

import numpy as np
import pytest

import candela
from conftest import shared_model


def largest_difference(a, b):
    return int(np.abs(a.astype(np.int16) - b.astype(np.int16)).max())


def test_the_orbit_cameras_metadata(device, grid):
    frame = device.render(grid, width=64, height=48, camera=candela.Camera.orbit(30.0, 70.0, 3.0, target=(0, 0, 0), fov_y=40.0))
    c = frame.camera
    theta, phi = math.radians(30.0), math.radians(70.0)
    np.testing.assert_allclose(c.camera_to_world[:3, 3],
                               3.0 * np.array([math.sin(phi) * math.sin(theta), math.cos(phi), math.sin(phi) * math.cos(theta)]),
                               atol=1e-5)
    np.testing.assert_allclose(c.camera_to_world[3], [0, 0, 0, 1])
    # The camera looks at the target down its -Z.
    forward = -c.camera_to_world[:3, 2]
    np.testing.assert_allclose(forward, -c.camera_to_world[:3, 3] / 3.0, atol=1e-5)
    focal = 48 / (2 * math.tan(math.radians(20.0)))
    np.testing.assert_allclose(c.K, [[focal, 0, 32], [0, focal, 24], [0, 0, 1]], rtol=1e-5)
    assert c.fov_y == pytest.approx(40.0) and c.near == pytest.approx(3e-3) and math.isinf(c.far)
    assert (c.width, c.height) == (64, 48) and not c.orthographic


def test_look_at_matrix_and_k_reproduce_the_orbit_camera(device, grid):
    orbit = device.render(grid, width=64, height=48, camera=candela.Camera.orbit(30.0, 70.0, 3.0, target=(0, 0, 0), fov_y=40.0))
    c = orbit.camera
    by_look_at = device.render(grid, width=64, height=48,
                               camera=candela.Camera.look_at(c.camera_to_world[:3, 3], (0, 0, 0), fov_y=40.0))
    by_matrix = device.render(grid, width=64, height=48, camera=candela.Camera.from_matrix(c.camera_to_world, K=c.K))
    assert largest_difference(orbit["color"], by_look_at["color"]) <= 1
    assert largest_difference(orbit["color"], by_matrix["color"]) <= 1
    np.testing.assert_allclose(by_matrix.camera.K, c.K, rtol=1e-5)
    np.testing.assert_allclose(by_look_at.camera.camera_to_world, c.camera_to_world, atol=1e-5)


def test_a_gltf_camera_by_index(device):
    cameras = device.load_scene(shared_model("Cameras"))
    perspective = device.render(cameras, width=64, height=48, camera=candela.Camera.gltf(0))
    assert not perspective.camera.orthographic and perspective.camera.fov_y > 0
    orthographic = device.render(cameras, width=64, height=48, camera=candela.Camera.gltf(1))
    assert orthographic.camera.orthographic and orthographic.camera.xmag > 0
    with pytest.raises(candela.InputError, match="cameras"):
        device.render(cameras, width=64, height=48, camera=candela.Camera.gltf(9))


def test_impossible_cameras_are_input_errors(device, grid):
    with pytest.raises(candela.InputError):
        candela.Camera.look_at((1, 2, 3), (1, 2, 3))
    with pytest.raises(candela.InputError, match="no skew"):
        candela.Camera(K=[[50, 1, 32], [0, 50, 24], [0, 0, 1]])
    with pytest.raises(candela.InputError, match="fov_y or K"):
        candela.Camera(fov_y=30, K=np.eye(3))
    with pytest.raises(candela.InputError, match="4x4"):
        candela.Camera.from_matrix(np.eye(3))
    with pytest.raises(candela.InputError, match="focal"):
        device.render(grid, width=8, height=8, camera=candela.Camera(K=[[0, 0, 4], [0, 1, 4], [0, 0, 1]]))
