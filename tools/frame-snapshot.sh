#!/usr/bin/env bash
# Renders the reshaping check set with one candela executable: 13 scenes, each on both shading
# paths, at 640x360 with --msaa 4, keeping each image (NAME.PATH.png) and its --explain lines
# (NAME.PATH.explain, the frame's decisions). A change that must not alter any image or decision
# (a reshaping) compares the snapshots of the executables before and after:
#   tools/frame-snapshot.sh BEFORE/candela /tmp/before
#   tools/frame-snapshot.sh build/release/app/candela /tmp/after
#   diff -r /tmp/before /tmp/after && echo identical
# Scenes come from SAMPLES (default ../shared/assets: the Khronos sample models and HDR files).
# Lines of --explain that report work in flight or caches (pipelines built or queued, the pipeline
# cache, timings) are left out: they vary between runs of one executable.
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: tools/frame-snapshot.sh CANDELA OUT_DIR" >&2
  exit 2
fi
candela=$(realpath "$1")
out=$2
samples=${SAMPLES:-$(dirname "$0")/../../shared/assets}
models=$samples/models
mkdir -p "$out"

helmet=$models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb
cases=(
  "default|"
  "grid10|--grid 10"
  "grid10-no-env|--grid 10 --env none"
  "helmet|--scene $helmet"
  "helmet-studio|--scene $helmet --env $samples/environments/studio_small_03_1k.hdr"
  "helmet-normals|--scene $helmet --debug-view mapped-normal"
  "toycar|--scene $models/ToyCar/glTF/ToyCar.gltf"
  "fox|--scene $models/Fox/glTF-Binary/Fox.glb --animation Run --time 0.4"
  "cesiumman|--scene $models/CesiumMan/glTF-Binary/CesiumMan.glb --time 1.1"
  "transmission|--scene $models/TransmissionTest/glTF-Binary/TransmissionTest.glb"
  "shoe|--scene $models/MaterialsVariantsShoe/glTF/MaterialsVariantsShoe.gltf --variant midnight"
  "lamp|--scene $models/IridescenceLamp/glTF/IridescenceLamp.gltf"
  "alphablend|--scene $models/AlphaBlendModeTest/glTF-Binary/AlphaBlendModeTest.glb"
)
for entry in "${cases[@]}"; do
  name=${entry%%|*}
  read -r -a flags <<<"${entry#*|}"
  for path in forward visibility; do
    "$candela" render "${flags[@]}" --shading-path "$path" --width 640 --height 360 --msaa 4 --quiet \
      --out "$out/$name.$path.png" --explain 2>&1 |
      grep -v -E '^(forward pipelines|pipeline cache):|[0-9.]+ ms\b' >"$out/$name.$path.explain" || true
    [ -s "$out/$name.$path.png" ] || { echo "frame-snapshot: $name ($path) made no image" >&2; exit 1; }
  done
  echo "$name"
done
