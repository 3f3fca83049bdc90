#!/usr/bin/env bash
# The CMake package (docs/embedding.md): the build installed into a temporary prefix; examples/embed
# configured as a project of its own with find_package(Candela 0.3 CONFIG) on that prefix, built and
# run on DamagedHelmet (from the shared assets; skipped when they are absent);
# its PNG must equal `candela render`'s of the same settings byte for byte.
#   tests/install/check-embed.sh BUILD_DIR SOURCE_DIR    (ctest: package.embed)
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
prefix=$tmp/prefix
export XDG_CACHE_HOME=$tmp/cache

cmake --install "$build" --prefix "$prefix" > "$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install"; }
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S "$source/examples/embed" -B "$tmp/embed" "${generator[@]}" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  > "$tmp/configure.log" 2>&1 || { cat "$tmp/configure.log"; fail "configuring examples/embed against $prefix"; }
cmake --build "$tmp/embed" > "$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; fail "building examples/embed"; }
# The example links the installed library, not the build tree's.
loaded=$(ldd "$tmp/embed/embed_candela")  # not piped into grep -q, whose early exit fails ldd with pipefail
grep -q "libcandela.so.* => $prefix/lib/libcandela.so" <<< "$loaded" ||
  fail "embed_candela does not load $prefix/lib/libcandela.so: $(grep candela <<< "$loaded")"

model=${CANDELA_SHARED_ASSETS:-$source/../shared/assets}/models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb
[ -f "$model" ] || { echo "skipped: $model is absent"; exit 77; }
mkdir "$tmp/run" && cd "$tmp/run"
"$tmp/embed/embed_candela" "$model" embedded.png || fail "embed_candela failed"
"$prefix/bin/candela" render --scene "$model" --width 512 --height 512 --out rendered.png > /dev/null || fail "candela render failed"
cmp embedded.png rendered.png || fail "the example's PNG differs from candela render's"
echo "identical: $(stat -c %s embedded.png) bytes"
echo "ok"
