#!/usr/bin/env bash
# The table of docs/scenes.md "Warnings against the glTF-Validator" (opt-in; needs node and npm):
# every glTF/GLB under the shared sample models rendered by `candela render` (its warning lines
# kept), the Khronos glTF-Validator (npm package gltf-validator, installed into a temporary
# folder) run on the same files, joined into one markdown table on stdout.
#   tools/warnings/run.sh [BUILD_DIR] [MODELS_DIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build/release}
models=${2:-../shared/assets/models}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && npm install --silent gltf-validator@2.0.0-dev.3.10 >/dev/null 2>&1)
NODE_PATH="$work/node_modules" node tools/validator/validate.js "$models" > "$work/validator.jsonl"
mkdir -p "$work/lines"
find "$models" -name '*.gltf' -o -name '*.glb' | sort | while read -r file; do
    rel=${file#"$models"/}
    "$build/app/candela" render --scene "$file" --env none --width 32 --height 32 --out "$work/x.png" \
        > /dev/null 2> "$work/lines/${rel//\//__}.txt" || true
done
node tools/warnings/table.js "$work/validator.jsonl" "$work/lines" "$models"
