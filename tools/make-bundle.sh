#!/usr/bin/env bash
# Packs a built tree into a relocatable folder (and a .tar.gz of it) that runs on another Linux
# x86-64 machine with a Vulkan driver and glibc 2.36 or newer, with nothing installed but the driver:
#   bin/candela, bin/candela_gpu_tests   the executable and the GPU test binary (stripped)
#   lib/                                 every shared library they and the validation layer link
#                                        but glibc's own (the Vulkan loader included)
#   lib/vulkan/explicit_layer.d/         the Khronos validation layer's manifest, pointing at
#                                        lib/libVkLayer_khronos_validation.so
#   share/candela/golden, test-data, test-scenes   what the GPU tests compare with and read
#   gpu-check.sh                         the check that runs there (tools/gpu-check.sh)
# Nothing inside holds a path of this machine: gpu-check.sh sets LD_LIBRARY_PATH, VK_LAYER_PATH
# and the tests' folders (tests/unit/test_paths.h) from where the bundle lies.
#   tools/make-bundle.sh [BUILD_DIR] OUT_DIR    -> OUT_DIR/candela-bundle/ and OUT_DIR/candela-bundle.tar.gz
# BUILD_DIR defaults to build/release (built with the GPU tests: CANDELA_BUILD_TESTS on).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ $# -eq 1 ]; then build=$root/build/release; out=$1
elif [ $# -eq 2 ]; then build=$1; out=$2
else echo "usage: tools/make-bundle.sh [BUILD_DIR] OUT_DIR" >&2; exit 2; fi

candela=$build/app/candela
tests=$build/tests/gpu/candela_gpu_tests
layer=$(ldconfig -p | awk '/libVkLayer_khronos_validation.so / && !found {print $NF; found = 1}')
manifest=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
[ -x "$candela" ] || { echo "error: $candela not built" >&2; exit 1; }
[ -n "$layer" ] && [ -f "$manifest" ] || { echo "error: the Khronos validation layer is not installed (vulkan-validationlayers)" >&2; exit 1; }

bundle=$out/candela-bundle
rm -rf "$bundle"
mkdir -p "$bundle/bin" "$bundle/lib/vulkan/explicit_layer.d" "$bundle/share/candela"
strip -o "$bundle/bin/candela" "$candela"
elves=("$candela" "$layer")
if [ -x "$tests" ]; then
  strip -o "$bundle/bin/candela_gpu_tests" "$tests"
  elves+=("$tests")
else
  echo "note: $tests not built; the bundle has no GPU tests" >&2
fi
cp "$layer" "$bundle/lib/"
python3 - "$manifest" "$bundle/lib/vulkan/explicit_layer.d/VkLayer_khronos_validation.json" <<'EOF'
import json, sys
manifest = json.load(open(sys.argv[1]))
manifest["layer"]["library_path"] = "../../libVkLayer_khronos_validation.so"  # relative to the manifest
json.dump(manifest, open(sys.argv[2], "w"), indent=4)
EOF

# The libraries: what ldd resolves for each ELF file, but glibc's (every Linux has its own, and
# they must match its ld.so).
glibc='^(libc|libm|libdl|libpthread|librt|libutil|libresolv|ld-linux-x86-64)\.so'
for elf in "${elves[@]}"; do
  ldd "$elf" | awk '$2 == "=>" && $3 ~ /^\// {print $3}'
done | sort -u | while read -r lib; do
  name=$(basename "$lib")
  [[ $name =~ $glibc ]] && continue
  cp -L "$lib" "$bundle/lib/$name"
done

cp -r "$root/tests/golden" "$bundle/share/candela/golden"
cp -r "$root/tests/data" "$bundle/share/candela/test-data"
cp -r "$root/assets/test-scenes" "$bundle/share/candela/test-scenes"
cp "$root/tools/gpu-check.sh" "$bundle/gpu-check.sh"
git -C "$root" describe --always --dirty > "$bundle/share/candela/commit" 2>/dev/null || true

tar -C "$out" -czf "$out/candela-bundle.tar.gz" candela-bundle
echo "$bundle: $(du -sh "$bundle" | cut -f1); $out/candela-bundle.tar.gz: $(du -h "$out/candela-bundle.tar.gz" | cut -f1)"
