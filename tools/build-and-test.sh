#!/usr/bin/env bash
# Installs what is missing, builds the release preset with tests, and runs its suite: GPU tests on
# lavapipe under the Khronos validation layer with synchronization validation, CLI tests of the real
# executable, the README's commands, the browser pages and the viewer under Xvfb. Then builds with
# AddressSanitizer + UndefinedBehaviorSanitizer and runs the unit tests (loaders on malformed input,
# graph compilation; built and run only here, once) and the CLI tests (the bad-input catalogue
# against the sanitized executable) again; those replay every input fuzzing ever found. The libFuzzer runs
# themselves are in tools/nightly.sh (CI time, docs/testing.md). Each stage's start is printed with
# the time since the script began.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
stage() { printf '\n=== [%dm%02ds] %s\n' $(((SECONDS - start) / 60)) $(((SECONDS - start) % 60)) "$*"; }

# Runs a GoogleTest binary as 8 shards, one per core at a time (the next shard starts when one
# ends, so a shard of long tests does not leave a core idle at the end), printing only failures and
# the summaries; fails when any shard fails or runs past 20 minutes. The sanitized stage runs its
# tests this way rather than one process per test through ctest: a sanitized process takes a
# moment to start and exit, which over ~700 tests was half of the stage.
sharded() {
  seq 0 7 | xargs -P "$(nproc)" -I{} env GTEST_TOTAL_SHARDS=8 GTEST_SHARD_INDEX={} timeout 1200 "$@" --gtest_brief=1
}

stage "install missing packages"
tools/install-deps.sh
stage "release build"
# Without the unit-test binaries: they are built and run sanitized below (CANDELA_UNIT_TESTS=ON, the
# default, builds them in a release tree too).
cmake --preset release -DCANDELA_UNIT_TESTS=OFF >/dev/null
cmake --build --preset release -j"$(nproc)"
stage "release tests"
# A failure's output scrolls far up among ~1,700 tests: the failed ones run again, alone, so that
# the end of the log shows why (and whether a failure repeats).
if ! ctest --preset release -j"$(nproc)" --timeout 600 --output-on-failure; then
  stage "the failed release tests again, one at a time"
  ctest --preset release --rerun-failed --timeout 600 --output-on-failure || true
  exit 1
fi
stage "sanitized build"
cmake --preset asan >/dev/null
# The CLI tests' own binary is the release one (below): what they test is the executable they run.
cmake --build --preset asan -j"$(nproc)" --target candela_unit_tests candela_engine_unit_tests candela
stage "sanitized unit tests"
sharded build/asan/tests/unit/candela_unit_tests
sharded build/asan/tests/unit/candela_engine_unit_tests
stage "sanitized CLI tests"
# The release build's CLI tests run the sanitized executable (CANDELA_EXECUTABLE; its parsing,
# batching and statistics tests in-process are the release stage's). The CLI tests start the Vulkan
# driver: LeakSanitizer off for them, as in tests/CMakeLists.txt.
# Allocation stacks 2 frames deep (ASan's default: 30; a report still names the allocating
# function), and without the ibl-report and quality-report sweeps, which ran in the release stage:
# under the sanitizers they took 156 s of the stage's 760 (docs/testing.md#ci-time); nor the work
# counters, which pin counts the release stage checked (39 s here, four full-size renders).
ASAN_OPTIONS=detect_leaks=0:malloc_context_size=2 CANDELA_EXECUTABLE=$PWD/build/asan/app/candela sharded build/release/tests/cli/candela_cli_tests \
  --gtest_filter='-Cli.QualityReport*:Cli.IblReport*:WorkCounters.*'
stage "done"
