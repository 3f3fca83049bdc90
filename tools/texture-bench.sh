#!/usr/bin/env bash
# Decode time and texture memory of a model's texture formats, from `candela bench`'s JSON: the
# folders tools/texture-variants.py writes (png, webp-lossless, webp-lossy, ktx2-etc1s, ktx2-uastc,
# ktx2-uastc-zstd), benchmarked in alternation for ROUNDS rounds; prints per variant the median
# texture decode time (ms and as a ratio to the same run's calibration pass), the scene load, the
# bytes in the files, the RGBA8 bytes decoded and the device memory of the textures.
#
#   tools/texture-bench.sh VARIANTS_DIR [ROUNDS]     (default 5 rounds)
set -euo pipefail
dir=$1
rounds=${2:-5}
candela=${CANDELA:-$(dirname "$0")/../build/release/app/candela}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
variants=()
for v in png webp-lossless webp-lossy ktx2-etc1s ktx2-uastc ktx2-uastc-zstd; do
  [ -d "$dir/$v" ] && variants+=("$v")
done
for round in $(seq "$rounds"); do
  for v in "${variants[@]}"; do
    gltf=$(ls "$dir/$v"/*.gltf | head -1)
    "$candela" bench --scene "$gltf" --frames 2 --width 320 --height 240 --json > "$out/$v.$round.json"
  done
done
/usr/bin/python3 - "$out" "${variants[@]}" <<'PY'
import json, statistics, sys, glob
out, variants = sys.argv[1], sys.argv[2:]
print(f"{'variant':<16} {'decode ms':>10} {'spread':>8} {'ratio':>7} {'load ms':>8} {'file MiB':>9} {'RGBA8 MiB':>10} {'device MiB':>11}  formats")
for v in variants:
    runs = [json.load(open(f)) for f in sorted(glob.glob(f"{out}/{v}.*.json"))]
    decode = [r["textures"]["decodeMs"] for r in runs]
    ratio = [r["textures"]["decodeMs"] / r["calibration"]["medianMs"] for r in runs]
    load = [r["sceneLoadMs"] for r in runs]
    t = runs[0]["textures"]
    mib = lambda b: b / 1048576
    print(f"{v:<16} {statistics.median(decode):>10.1f} {max(decode)-min(decode):>8.1f} {statistics.median(ratio):>7.1f} "
          f"{statistics.median(load):>8.1f} {mib(t['encodedBytes']):>9.2f} {mib(t['decodedBytes']):>10.2f} "
          f"{mib(t['deviceBytes']):>11.2f}  {t['formats']}")
PY
