# Per-pixel outputs from Python (docs/outputs.md): their arrays, the outputs without colour, bad
# names, and the transforms.json round trip — view A's depth re-projected into view B lands on B's.
import json

import numpy as np
import pytest

import candela


def test_outputs_are_arrays_of_their_channels(device, grid):
    frame = device.render(grid, width=64, height=48, outputs=["color", "depth", "normal", "ids", "metallic_roughness"])
    assert set(frame) == {"color", "depth", "normal", "metallic_roughness",
                          "node_id", "mesh_id", "primitive_id", "material_id", "instance_id"}
    assert frame["depth"].shape == (48, 64) and frame["depth"].dtype == np.float32
    assert frame["normal"].shape == (48, 64, 3) and frame["metallic_roughness"].shape == (48, 64, 2)
    assert frame["material_id"].dtype == np.uint32 and frame["material_id"].flags.c_contiguous
    empty = ~np.isfinite(frame["depth"])
    assert empty.any() and (~empty).any()
    # Nothing drawn: no ID, no normal; drawn: a unit normal and a material of the grid.
    assert (frame["material_id"][empty] == candela.NO_ID).all()
    assert (frame["material_id"][~empty] < 49).all()  # the 7 x 7 materials the grid picks from
    np.testing.assert_allclose(np.linalg.norm(frame["normal"][~empty], axis=1), 1.0, atol=1e-3)
    assert (frame["color"][..., 3][~empty] > 0).all()


def test_outputs_without_colour_leave_it_out(device, grid):
    frame = device.render(grid, width=32, height=32, outputs="depth")
    assert set(frame) == {"depth"}
    with pytest.raises(candela.InputError, match="'albedo' is not an output"):
        device.render(grid, width=8, height=8, outputs=["albedo"])


def test_depth_of_one_view_reprojects_onto_anothers(device, grid, tmp_path):
    views = [(20.0, 70.0), (45.0, 60.0)]
    frames = list(device.render_sequence(grid, width=160, height=120, views=views, outputs=["depth"]))
    # Through the transforms.json text, as a reconstruction tool reads it.
    document = json.loads(candela.transforms_json([(f"{i}.png", f) for i, f in enumerate(frames)]))
    K = np.array([[document["fl_x"], 0, document["cx"]], [0, document["fl_y"], document["cy"]], [0, 0, 1]])
    a, b = (np.array(f["transform_matrix"]) for f in document["frames"])
    depth_a, depth_b = frames[0]["depth"], frames[1]["depth"]
    v, u = np.nonzero(np.isfinite(depth_a))
    d = depth_a[v, u]
    # Pixel centres (u + ½, v + ½), v down; the camera looks down −Z with +Y up (OpenGL's axes).
    x = (u + 0.5 - K[0, 2]) / K[0, 0] * d
    y = -(v + 0.5 - K[1, 2]) / K[1, 1] * d
    points = a @ np.stack([x, y, -d, np.ones_like(d)])
    in_b = np.linalg.inv(b) @ points
    z = -in_b[2]
    ub = K[0, 0] * in_b[0] / z + K[0, 2] - 0.5
    vb = -K[1, 1] * in_b[1] / z + K[1, 2] - 0.5
    inside = (ub >= 1) & (ub < 159) & (vb >= 1) & (vb < 119)
    ub, vb, z = np.rint(ub[inside]).astype(int), np.rint(vb[inside]).astype(int), z[inside]
    # Within a pixel: z lies between the least and greatest of B's depths around where it lands
    # (B's surface passes through it there), unless something nearer hides the point from B.
    around = np.stack([depth_b[vb + dv, ub + du] for dv in (-1, 0, 1) for du in (-1, 0, 1)])
    low, high = np.min(around, axis=0), np.max(around, axis=0)
    on_surface = (z >= low * (1 - 1e-5)) & (z <= high * (1 + 1e-5))
    in_front = z < low * (1 - 1e-3)  # a point before everything B sees there: a wrong camera
    assert on_surface.mean() > 0.9, on_surface.mean()
    assert in_front.mean() < 0.002, in_front.mean()
