#!/usr/bin/env bash
# Before/after speed of two candela executables, measured as the project measures speed: alternated
# `candela bench` runs (before, then after, each round), each frame median as a ratio to the
# calibration pass of the same run. ROUNDS rounds of DamagedHelmet and the 10x10 sphere grid at
# 1280x720, 20 frames each; prints one line per run (ratio, min ratio, CPU build+record ms).
#   tools/bench-ab.sh 3 BEFORE/candela build/release/app/candela
# DamagedHelmet comes from SAMPLES (default ../shared/assets).
set -euo pipefail
if [ $# -ne 3 ]; then
  echo "usage: tools/bench-ab.sh ROUNDS BEFORE AFTER" >&2
  exit 2
fi
rounds=$1 before=$2 after=$3
samples=${SAMPLES:-$(dirname "$0")/../../shared/assets}
helmet=$samples/models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb
for round in $(seq 1 "$rounds"); do
  for scene in helmet grid; do
    for which in before after; do
      bin=$before
      [ "$which" = after ] && bin=$after
      args=(--grid 10)
      [ "$scene" = helmet ] && args=(--scene "$helmet")
      "$bin" bench "${args[@]}" --width 1280 --height 720 --frames 20 --json 2>/dev/null |
        python3 -c "import json, sys; f = json.load(sys.stdin)['frame']; \
print('round $round $scene $which: %.3fx (min %.3fx), CPU %.3f ms' % (f['medianRatio'], f['minRatio'], f['cpuMedianMs']))"
    done
  done
done
