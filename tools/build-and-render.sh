#!/usr/bin/env bash
# Installs what is missing, builds the release preset, and renders the default scene to
# candela.png (or the path given as the first argument).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)" --target candela
out="${1:-candela.png}"
build/release/app/candela render --out "$out"
