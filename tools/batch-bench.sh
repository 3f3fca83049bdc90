#!/usr/bin/env bash
# Renders every glTF file under a folder in one `candela render` run, and again with one process
# per file, alternating the two ROUNDS times (absolute times here vary up to 2x: only runs of the
# same round compare). Prints each round's totals and the ratio, the cost per scene, where the
# batch's time goes, and its memory: the peak, and what stays after each scene (flat when nothing
# is kept from one scene to the next).
#
# usage: tools/batch-bench.sh [MODELS_DIR] [ROUNDS] [SIZE]
#   MODELS_DIR  default ../shared/assets/models (the 85 sample files)
#   ROUNDS      default 2
#   SIZE        image width and height, default 512
set -euo pipefail
cd "$(dirname "$0")/.."
models=${1:-../shared/assets/models}
rounds=${2:-2}
size=${3:-512}
candela=build/release/app/candela
[ -x "$candela" ] || { echo "error: build first ($candela missing)" >&2; exit 1; }
work=$(mktemp -d /tmp/candela-batch-bench.XXXXXX)
trap 'rm -rf "$work"' EXIT
mapfile -t files < <(find "$models" -type f \( -iname '*.gltf' -o -iname '*.glb' \) | LC_ALL=C sort)
echo "${#files[@]} files under $models at ${size}x${size}, $rounds rounds"

now() { date +%s.%N; }
batch() {
  rm -rf "$work/batch"
  "$candela" render "$models" --out "$work/batch/{path}.png" --width "$size" --height "$size" \
    --report "$work/report.json" --quiet > "$work/batch.log" 2>&1 || true
}
separate() {
  rm -rf "$work/separate"
  mkdir -p "$work/separate"
  local i=0
  for f in "${files[@]}"; do
    "$candela" render --scene "$f" --out "$work/separate/$i.png" --width "$size" --height "$size" --quiet \
      > /dev/null 2>&1 || echo "  (separate: $f failed)"
    i=$((i + 1))
  done
}

for round in $(seq 1 "$rounds"); do
  # Alternate which goes first, so that neither always meets a warmer machine.
  if [ $((round % 2)) -eq 1 ]; then order="batch separate"; else order="separate batch"; fi
  declare -A took=()
  for what in $order; do
    start=$(now); $what; took[$what]=$(echo "$(now) - $start" | bc)
  done
  python3 - "${took[batch]}" "${took[separate]}" "${#files[@]}" "$round" <<'EOF'
import sys
batch, separate, n, round_ = float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
print(f"round {round_}: one run {batch:.2f} s ({batch / n:.3f} s a scene), one process per file {separate:.2f} s "
      f"({separate / n:.3f} s a scene); ratio {batch / separate:.3f}")
EOF
done

python3 - "$work/report.json" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
s = r["scenes"]
mib = lambda b: b / 2**20
load = sum(x["loadMs"] for x in s); wait = sum(x["loadWaitMs"] for x in s); upload = sum(x["uploadMs"] for x in s); frame = sum(sum(x["frameMs"]) for x in s)
print(f"last batch: {r['scenesRendered']} rendered, {r['scenesFailed']} failed; total {r['totalMs'] / 1000:.2f} s, "
      f"start-up {r['startupMs'] / 1000:.2f} s, precompute {r['precomputeMs'] / 1000:.2f} s ({r['precomputes']}x)")
print(f"  summed over scenes: load {load / 1000:.2f} s on the loading thread, of which rendering waited for "
      f"{wait / 1000:.2f} s (the rest overlapped the previous scene, or for the first the device's start); upload {upload / 1000:.2f} s, frames {frame / 1000:.2f} s")
print(f"  peak: host {mib(r['peakHostBytes']):.0f} MiB resident, device {mib(r['peakDeviceBytes']):.0f} MiB in use "
      f"({mib(r['peakDeviceMemoryBytes']):.0f} MiB held)")
ok = [x for x in s if x["status"] == "ok"]
for label, key in (("host resident", "retainedHostBytes"), ("device in use", "retainedDeviceBytes")):
    v = [mib(x[key]) for x in ok]
    q = [v[0], v[len(v) // 4], v[len(v) // 2], v[3 * len(v) // 4], v[-1]]
    print(f"  after each scene, released ({label}, MiB) at scenes 1, n/4, n/2, 3n/4, n: " +
          ", ".join(f"{x:.1f}" for x in q) + f"; min {min(v):.1f}, max {max(v):.1f}")
slow = sorted(ok, key=lambda x: -(x["loadMs"] + x["uploadMs"] + sum(x["frameMs"])))[:5]
print("  slowest: " + "; ".join(f"{x['path']} load {x['loadMs']:.0f} upload {x['uploadMs']:.0f} "
                                 f"frame {sum(x['frameMs']):.0f} ms" for x in slow))
EOF
