"""The installed Python module: `import candela` from PREFIX (not the build tree) renders a small
image of the built-in grid into a NumPy array. Run by check-install.sh, check-deb.sh and
check-tarball.sh with Debian's python3:  python3 check-python.py PREFIX"""
import sys
from pathlib import Path

import candela

prefix = Path(sys.argv[1]).resolve()
where = Path(candela.__file__).resolve()
assert prefix in where.parents, f"candela was imported from {where}, not from under {prefix}"
with candela.Device(pipeline_cache="off") as device:
    frame = device.render(candela.Scene.sphere_grid(3), width=32, height=24)
color = frame["color"]
assert color.shape == (24, 32, 4) and color.dtype.name == "uint8", color.shape
assert color[..., 3].max() == 255, "nothing drawn"
print(f"python: candela {candela.__version__} from {where.parent}: {color.shape[1]}x{color.shape[0]} rendered")
