#!/usr/bin/env bash
# Renders the image pairs of the ꟻLIP tests (tests/data/flip, tests/unit/reports/flip_reference_test.cpp):
# DamagedHelmet in venice_sunset at 128 x 128, as PNG and as EXR. The reference is drawn with
# MSAA 4; the test with MSAA 1, 4 prefilter samples and a 64-texel environment cube (aliased edges,
# a noisier reflection, a blurrier background): the kind of difference a regression makes.
#   tools/make-flip-test-images.sh [--build DIR] [OUT_DIR]   (default: tests/data/flip)
# Needs ../shared/assets. The expected values in the tests were computed from the committed files;
# re-rendering them (another driver, another Candela) changes the images, so the values must be
# computed again as docs/pipelines.md#how-the-tests-expected-values-were-obtained says.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build/release
if [ "${1:-}" = "--build" ]; then build="$2"; shift 2; fi
out="${1:-tests/data/flip}"
assets=../shared/assets
candela="$build/app/candela"
[ -x "$candela" ] || { echo "error: $candela not built" >&2; exit 1; }
mkdir -p "$out"
scene=(--scene "$assets/models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb"
       --env "$assets/environments/venice_sunset_1k.hdr" --width 128 --height 128 --quiet)
for ext in png exr; do
  "$candela" render "${scene[@]}" --msaa 4 --out "$out/helmet_reference.$ext" >/dev/null
  "$candela" render "${scene[@]}" --msaa 1 --ibl-prefilter-samples 4 --ibl-cube-size 64 \
    --out "$out/helmet_test.$ext" >/dev/null
  echo "wrote $out/helmet_reference.$ext and $out/helmet_test.$ext"
done
