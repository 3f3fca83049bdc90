#!/usr/bin/env bash
# A single render's time to image against its floor (docs/measurements.md, "The floor of one
# render"), measured together, ROUNDS times: `candela bench --cold 10` of SCENE at 1280x720 (the
# median of the warm renders), and the floor's terms measured alone in the same round — reading the
# file (2 ms, taken as measured once), decoding its textures in a fresh process
# (candela_decode_floor_bench: median of 5), one steady frame on the default path (`candela bench`:
# the forward path's frame median) and encoding and writing the PNG (`render --verbose`: median of
# 3). Prints per round the render, the floor and its terms, and their ratio.
#   tools/render-floor.sh [SCENE] [ROUNDS]     (default: DamagedHelmet, 3 rounds)
set -euo pipefail
samples=${SAMPLES:-$(dirname "$0")/../../shared/assets}
scene=${1:-$samples/models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb}
rounds=${2:-3}
build=${BUILD:-$(dirname "$0")/../build/release}
candela=$build/app/candela
decode=$build/tools/bench/candela_decode_floor_bench
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
median() { sort -n | awk '{v[NR]=$1} END {print v[int((NR+1)/2)]}'; }
for round in $(seq "$rounds"); do
  cold=$("$candela" bench --cold 10 --scene "$scene" | sed -nE 's/.*then: +median ([0-9.]+) ms.*/\1/p')
  dec=$(for i in 1 2 3 4 5; do "$decode" "$scene" | sed -nE 's/^texture decode ([0-9.]+) ms.*/\1/p'; done | median)
  frame=$("$candela" bench --scene "$scene" --frames 20 | sed -nE 's/^  path forward +frame median ([0-9.]+) ms \(([0-9.]+)x.*/\1 \2/p')
  enc=$(for i in 1 2 3; do "$candela" render --scene "$scene" --out "$out/f.png" --verbose 2>&1 |
          sed -nE 's/.*encoding and writing ([0-9.]+) ms.*/\1/p'; done | median)
  /usr/bin/python3 - "$cold" "$dec" $frame "$enc" <<'PY'
import sys
cold, dec, frame, ratio, enc = map(float, sys.argv[1:])
cal = frame / ratio
floor = 2.0 + dec + frame + enc
print(f"render {cold:.0f} ms ({cold / cal:.1f}x cal) | floor {floor:.0f} ms ({floor / cal:.1f}x cal): "
      f"decode {dec:.0f}, frame {frame:.1f} ({ratio:.2f}x cal), encode {enc:.0f}, file 2 | render / floor {cold / floor:.2f}")
PY
done
