#!/usr/bin/env bash
# The relocatable tarball (docs/packaging.md): unpacked into a temporary folder (its path holds a
# space), its executable finds every shared library it needs but glibc's in the tarball's lib/
# through its run path, nothing in it holds the path of the source or build folder, and it renders
# the default scene and a sample model (DamagedHelmet, when the shared assets are there) from an
# empty folder; its gpu-check.sh runs the steps that need no test binary and writes its report.
#   tests/install/check-tarball.sh PACKAGE_DIR BUILD_DIR SOURCE_DIR    (ctest: package.tarball)
set -euo pipefail
packages=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
source=$(cd "$3" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

tarballs=("$packages"/candela-*-linux-x86_64.tar.gz)
[ -f "${tarballs[0]}" ] || fail "no tarball in $packages (the package.build test makes it)"
mkdir "$tmp/some where"
tar -C "$tmp/some where" -xzf "${tarballs[0]}"
top=$(echo "$tmp/some where"/candela-*)
echo "unpacked: $(find "$top" -type f | wc -l) files, $(du -sh "$top" | cut -f1)"

runpath=$(readelf -d "$top/bin/candela" | sed -n 's/.*(RPATH).*\[\(.*\)\]/\1/p')
[ "$runpath" = '$ORIGIN/../lib' ] || fail "bin/candela's RPATH is '$runpath', not \$ORIGIN/../lib"
glibc='^(libc|libm|libdl|libpthread|librt|libutil|libresolv|libmvec|ld-linux-x86-64)\.so'
while read -r name path; do
  [[ $name =~ $glibc ]] && continue
  path=$(realpath "$path")
  [[ $path == "$top/lib/"* ]] || fail "bin/candela loads $name from $path, not from the tarball's lib/"
done < <(env -u LD_LIBRARY_PATH ldd "$top/bin/candela" | sed -n 's/^\s*\(\S*\) => \(.*\) (0x[0-9a-f]*)$/\1 \2/p')
[ -f "$top/share/doc/candela/third-party/libglfw3/copyright" ] || fail "no copyright file for the bundled libglfw"

held=$(grep -rlF -e "$source/" -e "$build/" "$top" || true)
[ -z "$held" ] || fail "these files hold the path of $source or $build: $held"

mkdir "$tmp/empty"
cd "$tmp/empty"
export XDG_CACHE_HOME=$tmp/cache
env -u LD_LIBRARY_PATH "$top/bin/candela" --version
env -u LD_LIBRARY_PATH "$top/bin/candela" render --width 96 --height 54 --out grid.png || fail "the default scene"
[ -s grid.png ] || fail "no grid.png"
helmet=${CANDELA_SHARED_ASSETS:-$source/../shared/assets}/models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb
if [ -f "$helmet" ]; then
  env -u LD_LIBRARY_PATH "$top/bin/candela" render --scene "$helmet" --width 96 --height 96 --out helmet.png || fail "DamagedHelmet"
  [ -s helmet.png ] || fail "no helmet.png"
else
  echo "note: $helmet is absent; only the default scene rendered"
fi
# The Python module, with PYTHONPATH at the tarball's dist-packages: it loads libcandela.so from
# the tarball's lib/.
site=$(find "$top/lib" -maxdepth 2 -name dist-packages -type d)
[ -n "$site" ] || fail "no Python package in the tarball"
module=$(find "$site/candela" -name '_candela*.so')
linked=$(env -u LD_LIBRARY_PATH ldd "$module" 2>&1 || true)
grep -q "libcandela.so.* => $top/lib/" <<< "$linked" ||
  fail "the Python module ($module) does not load the tarball's libcandela.so; ldd says: $(grep -i -e candela -e 'not found' <<< "$linked" | tr -s ' \t\n' ' ')"
env -u LD_LIBRARY_PATH PYTHONPATH="$site" /usr/bin/python3 "$source/tests/install/check-python.py" "$top" || fail "import candela"

# The GPU check runs from it too: without the test binary and the layer, what the executable can.
"$top/gpu-check.sh" --out "$tmp/report" --bench-frames 2 2> "$tmp/steps" || { cat "$tmp/steps" >&2; fail "gpu-check.sh"; }
for line in "validation: off (no validation layer in the tarball)" "- render-default-forward: exit 0" \
            "- render-default-visibility: exit 0" "| built-in: sphere grid 10x10 |"; do
  grep -qF -- "$line" "$tmp/report/report.md" || { cat "$tmp/report/report.md" >&2; fail "gpu-check's report lacks: $line"; }
done
echo "ok"
