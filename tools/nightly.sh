#!/usr/bin/env bash
# The opt-in long checks that do not fit CI's 25 minutes (docs/testing.md): a bounded libFuzzer run
# of each file reader (clang, ASan + UBSan; docs/fuzzing.md) — by default 60 s of glTF/GLB beside
# 30 s each of Radiance .hdr and OpenEXR, one per core; `tools/nightly.sh 600` runs 600 s and 300 s.
# Inputs it finds become regression files that CI replays (tests/unit/assets/fuzz_regression_test.cpp).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
tools/install-deps.sh
FUZZ_STEP=prepare tools/fuzz.sh
FUZZ_STEP=run tools/fuzz.sh "$seconds" gltf &
gltf=$!
status=0
FUZZ_STEP=run tools/fuzz.sh $((seconds / 2)) hdr exr || status=1
wait "$gltf" || status=1
exit "$status"
