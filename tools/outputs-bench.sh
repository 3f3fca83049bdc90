#!/usr/bin/env bash
# What each per-pixel output costs (docs/outputs.md), measured as the project measures speed:
# alternated `candela bench` runs of DamagedHelmet at 1280x720, 20 frames each, colour alone and
# colour with each output set, each frame median as a ratio to the calibration pass of the same
# run. Prints one line per run, then per set the median over the rounds and its cost over colour
# alone (both as ratios to the calibration).
#   tools/outputs-bench.sh 3 build/release/app/candela
# DamagedHelmet comes from SAMPLES (default ../shared/assets).
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: tools/outputs-bench.sh ROUNDS CANDELA" >&2
  exit 2
fi
rounds=$1 candela=$2
samples=${SAMPLES:-$(dirname "$0")/../../shared/assets}
helmet=$samples/models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb
sets=(color color,depth color,normal color,base_color,alpha color,metallic_roughness color,emissive color,ids
      color,depth,normal,ids "color,depth,clip_depth,normal,base_color,alpha,metallic_roughness,emissive,ids" depth,normal,ids)
results=$(mktemp)
trap 'rm -f "$results"' EXIT
for round in $(seq 1 "$rounds"); do
  for set in "${sets[@]}"; do
    "$candela" bench --scene "$helmet" --width 1280 --height 720 --frames 20 --outputs "$set" --json 2>/dev/null |
      python3 -c "import json, sys; f = json.load(sys.stdin)['frame']; print('$set', f['medianRatio'])" | tee -a "$results"
  done
done
python3 - "$results" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    name, ratio = line.split()
    runs.setdefault(name, []).append(float(ratio))
base = statistics.median(runs["color"])
for name, ratios in runs.items():
    m = statistics.median(ratios)
    print(f"{name:75s} {m:7.3f}x calibration  {m - base:+7.3f}x  ({(m / base - 1) * 100:+.1f}% of colour alone)")
PY
