#!/usr/bin/python3
"""The Python module's overhead per image (docs/python.md#overhead): the median time of one
device.render() from Python against one Device::render through the C++ API
(candela_api_render_bench), same scene, size and sky, in alternated rounds.

    PYTHONPATH=build/release/python tools/python-overhead.py build/release [SCENE|grid] [--size 64] [--rounds 5] [--renders 50]
"""
import argparse
import statistics
import subprocess
import time
from pathlib import Path

import candela

parser = argparse.ArgumentParser()
parser.add_argument("build", type=Path)
parser.add_argument("scene", nargs="?", default="grid")
parser.add_argument("--size", type=int, default=64)
parser.add_argument("--rounds", type=int, default=5)
parser.add_argument("--renders", type=int, default=50)
args = parser.parse_args()
bench = args.build / "tools" / "bench" / "candela_api_render_bench"


def python_round():
    with candela.Device(pipeline_cache="off") as device:
        scene = candela.Scene.sphere_grid() if args.scene == "grid" else device.load_scene(args.scene)
        sky = device.load_environment()
        for _ in range(5):
            device.render(scene, width=args.size, height=args.size, environment=sky)
        times = []
        for _ in range(args.renders):
            start = time.perf_counter()
            device.render(scene, width=args.size, height=args.size, environment=sky)
            times.append((time.perf_counter() - start) * 1e3)
    return statistics.median(times)


def cpp_round():
    out = subprocess.run([str(bench), args.scene, str(args.size), str(args.size), str(args.renders)],
                         check=True, capture_output=True, text=True).stdout
    return float(out.split()[0].split("=")[1])


python_ms, cpp_ms = [], []
for _ in range(args.rounds):
    cpp_ms.append(cpp_round())
    python_ms.append(python_round())
ratios = [p / c for p, c in zip(python_ms, cpp_ms)]
print(f"{args.scene} at {args.size}x{args.size}, {args.rounds} rounds of {args.renders} renders")
print("C++ API ms:  " + " ".join(f"{t:.3f}" for t in cpp_ms))
print("Python ms:   " + " ".join(f"{t:.3f}" for t in python_ms))
print("Python/C++:  " + " ".join(f"{r:.3f}" for r in ratios) + f"  (median {statistics.median(ratios):.3f})")
