"""Datasets of a library of glTF files: every object rendered from many views, with its images and
cameras (transforms.json) in a folder of its own, across the worker processes of a Dask cluster —
one Candela device per process, one task per file, a failed file reported and the rest rendered,
one manifest for the whole run (docs/datasets.md).

    from dask.distributed import Client, LocalCluster
    from candela.datasets import render_library

    with LocalCluster(n_workers=4, threads_per_worker=1) as cluster, Client(cluster) as client:
        manifest = render_library(client, ["models/"], "dataset/", views=50, width=512, height=512)
"""

import json
import os
import tempfile
import time
from pathlib import Path

import numpy

import candela

__all__ = ["list_scenes", "object_complete", "render_object", "render_library", "worker_device"]

_device = None
_device_options = None


def worker_device(**options):
    """The Candela device of this process, made on first use with `options` (candela.Device's
    keywords) and kept for the process's life: a Dask worker process renders all its tasks on one
    device, as `candela render` renders a library on one."""
    global _device, _device_options
    if _device is None:
        _device = candela.Device(**options)
        _device_options = options
    elif options != _device_options:
        raise candela.Error(f"this process's device was made with {_device_options}, not {options}")
    return _device


def list_scenes(inputs):
    """The .gltf and .glb files of `inputs` (files, and folders walked in sorted order), each once."""
    found, seen = [], set()
    for entry in inputs:
        entry = Path(entry)
        files = sorted(p for p in entry.rglob("*") if p.suffix.lower() in (".gltf", ".glb")) if entry.is_dir() else [entry]
        for file in files:
            key = file.resolve()
            if key not in seen:
                seen.add(key)
                found.append(file)
    return found


def _write_atomically(path, write):
    """Writes `path` through a temporary file in its folder renamed into place (as Candela's writers)."""
    path = Path(path)
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=path.name + ".tmp-")
    try:
        with os.fdopen(handle, "wb") as out:
            write(out)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def _object_files(folder, count):
    return [folder / f"{i:03d}.png" for i in range(count)] + [folder / "transforms.json"]


def object_complete(folder, views):
    """Whether `folder` holds a finished object: its transforms.json (written last) lists `views`
    frames whose files (the image and every OUTPUT_file_path) are all there."""
    transforms = Path(folder) / "transforms.json"
    try:
        frames = json.loads(transforms.read_text())["frames"]
    except (OSError, ValueError, KeyError):
        return False
    return len(frames) == views and all((Path(folder) / f[key]).is_file()
                                        for f in frames for key in f if key.endswith("file_path"))


def render_object(scene_file, out_folder, *, views=20, ring=None, lighting_seed=None, environment=None,
                  device_options=None, resume=True, **settings):
    """Renders `scene_file` from `views` directions (a Fibonacci sphere, or a ring `ring` degrees
    above the horizon) into `out_folder`: NNN.png per view, with `outputs=` besides colour each
    output as NNN.OUTPUT.npy (named in the view's transforms.json entry as OUTPUT_file_path, e.g.
    depth_file_path), and transforms.json (written last, so a folder with it is finished).
    `environment`: an .hdr/.exr path, None for the built-in sky. `settings`: Device.render's
    keywords. Returns the object's manifest entry; a Candela error is returned as a failure of
    this file, not raised."""
    start = time.perf_counter()
    entry = {"file": str(scene_file), "folder": str(out_folder), "worker": os.getpid()}
    try:
        out_folder = Path(out_folder)
        if resume and object_complete(out_folder, views):
            return {**entry, "status": "complete", "seconds": 0.0}
        out_folder.mkdir(parents=True, exist_ok=True)
        device = worker_device(**(device_options or {}))
        scene = device.load_scene(scene_file)
        lighting = device.load_environment(environment)
        directions = candela.ring_views(views, ring) if ring is not None else candela.sphere_views(views)
        validation_before = device.validation_messages
        frames = []
        extra = []  # per view: the files of its outputs besides colour
        for i, frame in enumerate(device.render_sequence(scene, views=directions, lighting_seed=lighting_seed,
                                                         environment=lighting, **settings)):
            name = f"{i:03d}.png"
            if "color" in frame:
                candela.write_image(out_folder / name, frame["color"])
            files = {}
            for output, values in frame.items():
                if output == "color":
                    continue
                files[f"{output}_file_path"] = f"{i:03d}.{output}.npy"
                _write_atomically(out_folder / files[f"{output}_file_path"], lambda out, v=values: numpy.save(out, v))
            frames.append((name, frame))
            extra.append(files)
        text = candela.transforms_json(frames)
        if any(extra):
            document = json.loads(text)
            for entry_json, (_, frame), files in zip(document["frames"], frames, extra):
                entry_json.update(files)
                if "color" not in frame:  # no image was written
                    del entry_json["file_path"]
            text = json.dumps(document, indent=2) + "\n"
        _write_atomically(out_folder / "transforms.json", lambda out: out.write(text.encode()))
        return {**entry, "status": "ok", "views": views, "warnings": list(scene.warnings),
                "validation_messages": device.validation_messages - validation_before,
                "seconds": time.perf_counter() - start}
    except (candela.Error, OSError) as error:  # Candela's one-line message; a file that cannot be written
        return {**entry, "status": "failed", "error": str(error), "seconds": time.perf_counter() - start}


def render_library(client, inputs, out, *, views=20, manifest="manifest.json", **options):
    """Renders every glTF file of `inputs` with render_object on the workers of the Dask `client`,
    one task per file, into out/<file's path without extension>/ (relative to the folder it was
    found in). Gathers the entries, in the files' order, into out/`manifest` (written atomically)
    and returns it: per file its status ("ok", "complete" when a finished folder was there already,
    "failed" with the error — Candela's, a file that could not be written, or the task's when its
    worker process was lost), worker and time, and the run's counts."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    tasks = []
    for entry in inputs:
        entry = Path(entry)
        for file in list_scenes([entry]):
            relative = file.relative_to(entry) if entry.is_dir() else Path(file.name)
            tasks.append((file, out / relative.with_suffix("")))
    start = time.perf_counter()
    futures = [client.submit(render_object, str(file), str(folder), views=views, pure=False, **options)
               for file, folder in tasks]
    # In the files' order; a task that died (its worker process lost) is that file's failure.
    objects = []
    for (file, folder), future in zip(tasks, futures):
        try:
            objects.append(future.result())
        except Exception as error:  # noqa: BLE001 - whatever the cluster raised, reported per file
            objects.append({"file": str(file), "folder": str(folder), "status": "failed",
                            "error": f"{file}: the task failed: {type(error).__name__}: {error}"})
    result = {"candela": candela.__version__, "views": views, "seconds": time.perf_counter() - start,
              "counts": {status: sum(o["status"] == status for o in objects) for status in ("ok", "complete", "failed")},
              "objects": objects}
    text = json.dumps(result, indent=2) + "\n"
    _write_atomically(out / manifest, lambda f: f.write(text.encode()))
    return result
