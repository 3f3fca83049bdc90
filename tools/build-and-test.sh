#!/usr/bin/env bash
# Installs what is missing, builds the release preset with tests, and runs the whole suite:
# unit tests (no GPU), GPU tests on lavapipe under the Khronos validation layer with
# synchronization validation, CLI tests of the real executable, and the viewer under Xvfb. Then
# builds with AddressSanitizer + UndefinedBehaviorSanitizer and runs the unit tests (loaders on
# malformed input, graph compilation) and the CLI tests (the bad-input catalogue against the
# sanitized executable) again. Last, a bounded libFuzzer run of each file reader (clang, ASan +
# UBSan; docs/fuzzing.md): 60 s of glTF/GLB, 30 s each of Radiance .hdr and OpenEXR.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
ctest --preset release -j"$(nproc)" --timeout 600
cmake --preset asan >/dev/null
cmake --build --preset asan -j"$(nproc)" --target candela_unit_tests candela candela_cli_tests
ctest --preset asan -j"$(nproc)" --timeout 600 -L 'unit|cli'
tools/fuzz.sh 60 gltf
tools/fuzz.sh 30 hdr exr
