#!/usr/bin/env bash
# tools/make-bundle.sh and tools/gpu-check.sh on lavapipe: the bundle holds every library its
# programs link but glibc's (resolved from its lib/ alone), and the check, run from the unpacked
# tarball in another folder on one golden case, one GPU test and 2 bench frames, writes a report
# whose every step ran and whose figures are lavapipe's own (the golden renders equal the approved
# images within the goldens' tolerances; a still scene's repeated frames are identical).
#   tests/cli/gpu_check_test.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "$1" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAILED: $*" >&2; exit 1; }

"$root/tools/make-bundle.sh" "$build" "$tmp/made" > /dev/null
mkdir "$tmp/elsewhere"
tar -C "$tmp/elsewhere" -xzf "$tmp/made/candela-bundle.tar.gz"
bundle=$tmp/elsewhere/candela-bundle

# Every library resolves inside the bundle, or is glibc's.
glibc='^(libc|libm|libdl|libpthread|librt|libutil|libresolv|ld-linux-x86-64)\.so|linux-vdso'
for elf in "$bundle/bin/candela" "$bundle/bin/candela_gpu_tests" "$bundle/lib/libVkLayer_khronos_validation.so"; do
  LD_LIBRARY_PATH=$bundle/lib ldd "$elf" | while read -r name arrow path _; do
    [[ $name =~ $glibc ]] && continue
    [ "$arrow" = "=>" ] || continue
    [[ $path == "$bundle/lib/"* ]] || fail "$(basename "$elf"): $name resolves to $path, not the bundle"
  done
done
grep -q '"library_path": "../../libVkLayer_khronos_validation.so"' \
  "$bundle/lib/vulkan/explicit_layer.d/VkLayer_khronos_validation.json" || fail "layer manifest"
! grep -rq "$root" "$bundle/lib/vulkan" "$bundle/gpu-check.sh" || fail "a path of the source tree in the bundle"

cd "$tmp"
"$bundle/gpu-check.sh" --out "$tmp/report" --golden-filter '/default_scene' --tests-filter 'ContextLifetime.*' \
  --bench-frames 2 --tests-timeout 120 2> "$tmp/steps" || { cat "$tmp/steps" >&2; fail "gpu-check.sh exited non-zero"; }
report=$tmp/report/report.md
expect() { grep -qF -- "$1" "$report" || { cat "$report" >&2; fail "report lacks: $1"; }; }
expect "layers enabled: VK_LAYER_KHRONOS_validation"
expect "- golden: 2 run, 2 passed, 0 failed"
expect "### forward path: 1 images compared, 43 without a render"
expect "### visibility path: 1 images compared, 43 without a render"
expect "| default_scene.png |"
for path in forward visibility; do
  for msaa in 1 4; do
    expect "- frames-$path-msaa$msaa (exit 0): ok             frames-$path-msaa$msaa-1.png: 640x360, FLIP mean 0.000000"
  done
done
expect "- render-default-forward: exit 0"
expect "- render-default-visibility: exit 0"
expect "| built-in: sphere grid 10x10 |"
total=$(grep -o "gpu-tests-[0-3]: [0-9]* run, [0-9]* passed, 0 failed" "$report" | awk '{s += $2; p += $4} END {print s, p}')
[ "$total" = "1 1" ] || { cat "$report" >&2; fail "GPU tests: expected 1 run and passed over the shards, got $total"; }
echo "gpu-check: bundle and report as expected"
