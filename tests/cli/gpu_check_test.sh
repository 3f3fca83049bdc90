#!/usr/bin/env bash
# The GPU check's tarball (`cpack -G TGZ -D CANDELA_GPU_CHECK=ON`) and tools/gpu-check.sh on
# lavapipe: the tarball holds every library its programs and the validation layer link but glibc's
# (its programs find them by their run path, the layer by the loader's), and the check, run from
# the unpacked tarball in another folder on one golden case, one GPU test, 2 bench frames and 2 cold
# runs, writes a report whose every step ran and whose figures are lavapipe's own (the golden renders equal the approved
# images within the goldens' tolerances; a still scene's repeated frames are identical).
#   tests/cli/gpu_check_test.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "$1" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAILED: $*" >&2; exit 1; }

cpack --config "$build/CPackConfig.cmake" -G TGZ -D CANDELA_GPU_CHECK=ON -B "$tmp/made" > "$tmp/cpack.log" 2>&1 ||
  { cat "$tmp/cpack.log" >&2; fail "cpack"; }
mkdir "$tmp/elsewhere"
tar -C "$tmp/elsewhere" -xzf "$tmp/made"/candela-*-gpu-check.tar.gz
bundle=$(echo "$tmp/elsewhere"/candela-*)

# Every library resolves inside the tarball, or is glibc's: the programs' by their run path, the
# layer's (loaded by the tarball's Vulkan loader) as the loader's own.
glibc='^(libc|libm|libdl|libpthread|librt|libutil|libresolv|libmvec|ld-linux-x86-64)\.so|linux-vdso'
check() {  # ELF [LD_LIBRARY_PATH]
  env -u LD_LIBRARY_PATH ${2:+LD_LIBRARY_PATH=$2} ldd "$1" | while read -r name arrow path _; do
    [[ $name =~ $glibc ]] && continue
    [ "$arrow" = "=>" ] || continue
    [[ $(realpath "$path") == "$bundle/lib/"* ]] || fail "$(basename "$1"): $name resolves to $path, not the tarball"
  done
}
check "$bundle/bin/candela"
check "$bundle/bin/candela_gpu_tests"
check "$bundle/lib/libVkLayer_khronos_validation.so" "$bundle/lib"
grep -Eq '"library_path" *: *"../../libVkLayer_khronos_validation.so"' \
  "$bundle/lib/vulkan/explicit_layer.d/VkLayer_khronos_validation.json" || fail "layer manifest"
! grep -rq "$root" "$bundle/lib/vulkan" "$bundle/gpu-check.sh" || fail "a path of the source tree in the bundle"

cd "$tmp"
"$bundle/gpu-check.sh" --out "$tmp/report" --golden-filter '/default_scene' --tests-filter 'ContextLifetime.*' \
  --bench-frames 2 --cold-runs 2 --tests-timeout 120 2> "$tmp/steps" || { cat "$tmp/steps" >&2; fail "gpu-check.sh exited non-zero"; }
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
grep -Eq '^\| default \| [0-9]+ ms \| [0-9]+ ms \| [0-9]+ ms \| [0-9.]+x \|$' "$report" ||
  { cat "$report" >&2; fail "report lacks the default scene's time to image"; }
[ ! -e "$tmp/report/cache" ] || fail "the time-to-image caches were left behind"
total=$(grep -o "gpu-tests-[0-3]: [0-9]* run, [0-9]* passed, 0 failed" "$report" | awk '{s += $2; p += $4} END {print s, p}')
[ "$total" = "1 1" ] || { cat "$report" >&2; fail "GPU tests: expected 1 run and passed over the shards, got $total"; }
echo "gpu-check: bundle and report as expected"
