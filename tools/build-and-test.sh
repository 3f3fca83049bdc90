#!/usr/bin/env bash
# Installs what is missing, builds the release preset with tests, and runs the whole suite:
# unit tests (no GPU), GPU tests on lavapipe under the Khronos validation layer with
# synchronization validation, and CLI tests of the real executable.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
ctest --preset release -j"$(nproc)" --timeout 600
