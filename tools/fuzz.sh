#!/usr/bin/env bash
# Fuzzes the file readers with libFuzzer (docs/fuzzing.md): builds the fuzz preset (clang,
# AddressSanitizer + UndefinedBehaviorSanitizer, coverage), writes the seed corpora, then runs each
# harness for a bounded time on its seeds plus every input that once crashed it
# (tests/fuzz/regressions/TARGET). Exits non-zero on the first crash, leak, sanitizer report,
# timeout or invariant violation; the input is saved as build/fuzz/artifacts/TARGET-*.
#
#   tools/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]      defaults: 60 s; gltf hdr exr ktx2 webp npy lod_cache scene_list compared_image
#   FUZZ_RUNS=N tools/fuzz.sh 0 gltf                     run N executions instead of a time
#   FUZZ_STEP=prepare tools/fuzz.sh                      only build and write the seeds
#   FUZZ_STEP=run tools/fuzz.sh 30 hdr                   only run (after a prepare): two such runs
#                                                        may go in parallel, one per core
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(gltf hdr exr ktx2 webp npy lod_cache scene_list compared_image)

build=build/fuzz
bin=$build/tests/fuzz
if [ "${FUZZ_STEP:-all}" != run ]; then
  cmake --preset fuzz >/dev/null
  cmake --build --preset fuzz -j"$(nproc)"
  rm -rf "$build/seeds"
  "$bin/make_fuzz_seeds" "$build/seeds"
  mkdir -p "$build/artifacts"
fi
[ "${FUZZ_STEP:-all}" = prepare ] && exit 0

for target in "${targets[@]}"; do
  work="$build/corpus/$target"  # grows across local runs; new inputs land here
  mkdir -p "$work"
  # Every input that ever failed, where the target has had a finding.
  regressions=()
  [ -d "tests/fuzz/regressions/$target" ] && regressions=("tests/fuzz/regressions/$target")
  limit=(-max_total_time="$seconds")
  [ -n "${FUZZ_RUNS:-}" ] && limit=(-runs="$FUZZ_RUNS")
  echo "fuzz_$target: ${FUZZ_RUNS:+$FUZZ_RUNS runs}${FUZZ_RUNS:-$seconds s}"
  # -timeout: one input may take at most 10 s (a hang is a finding); -rss_limit_mb: 2 GiB.
  "$bin/fuzz_$target" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$build/artifacts/$target-" "$work" "$build/seeds/$target" "${regressions[@]}" \
    2>"$build/fuzz-$target.log" || { tail -60 "$build/fuzz-$target.log"; exit 1; }
  grep -E "^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)" "$build/fuzz-$target.log"
  grep -E "^#[0-9]+ +DONE" "$build/fuzz-$target.log" || true
done
