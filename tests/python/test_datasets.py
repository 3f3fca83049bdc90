# A library rendered into a dataset across a Dask LocalCluster of two worker processes
# (candela.datasets, docs/datasets.md): every file rendered once, a broken file reported with
# its message while the rest complete, one manifest; a second run finds the objects finished.
import json
import os
import shutil

import numpy as np
import pytest

from conftest import shared_model

distributed = pytest.importorskip("dask.distributed")

from candela.datasets import object_complete, render_library  # noqa: E402

NAMES = ("Box", "Duck", "BoxTextured", "AnimatedCube")


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        yield client


def test_a_library_across_two_workers(client, tmp_path):
    library = tmp_path / "library"
    library.mkdir()
    for name in NAMES:
        model = shared_model(name)  # a .gltf with its .bin and images, or a .glb
        shutil.copytree(model.parent, library / name)
    (library / "broken.glb").write_bytes(b"glTF\x02\x00\x00\x00\x10\x00\x00\x00nonsense")
    out = tmp_path / "dataset"
    options = dict(views=3, width=48, height=40, outputs=["color", "depth", "normal", "ids"],
                   device_options={"validation": True, "pipeline_cache": "off"})
    manifest = render_library(client, [library], out, **options)

    objects = manifest["objects"]
    assert sorted(o["file"] for o in objects) == sorted(str(p) for p in [*library.glob("*/*.gl*"), library / "broken.glb"])
    assert manifest["counts"] == {"ok": len(NAMES), "complete": 0, "failed": 1}
    broken = next(o for o in objects if o["file"].endswith("broken.glb"))
    assert broken["status"] == "failed" and broken["error"].startswith(str(library / "broken.glb") + ": ")
    for o in objects:
        if o is broken:
            continue
        assert o["status"] == "ok" and o["validation_messages"] == 0, o
        folder = out / os.path.relpath(o["file"], library)
        folder = folder.with_suffix("")
        assert object_complete(folder, 3)
        transforms = json.loads((folder / "transforms.json").read_text())
        assert [f["file_path"] for f in transforms["frames"]] == ["000.png", "001.png", "002.png"]
        assert transforms["w"] == 48 and transforms["h"] == 40
        # The outputs besides colour beside each view, named in its entry.
        first = transforms["frames"][0]
        assert first["depth_file_path"] == "000.depth.npy" and first["node_id_file_path"] == "000.node_id.npy"
        depth, normal = np.load(folder / first["depth_file_path"]), np.load(folder / first["normal_file_path"])
        assert depth.shape == (40, 48) and normal.shape == (40, 48, 3) and np.isfinite(depth).any()
        assert np.load(folder / first["material_id_file_path"]).dtype == np.uint32
    assert json.loads((out / "manifest.json").read_text())["counts"] == manifest["counts"]
    assert not list(out.rglob("*.tmp-*"))

    # Again: the finished objects are found complete, not rendered; the broken file fails again.
    again = render_library(client, [library], out, **options)
    assert again["counts"] == {"ok": 0, "complete": len(NAMES), "failed": 1}
