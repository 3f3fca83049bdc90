#!/usr/bin/env bash
# The public API's surface (docs/embedding.md): each header of include/candela/ compiles alone in a
# translation unit that includes nothing else, with -Wall -Wextra -Werror -pedantic, and reaches no
# header but its siblings and the C++ standard library's (the packages of GCC's and glibc's
# headers: nothing from Vulkan, GLFW, GLM or tinygltf); libcandela.so exports only the API's
# symbols (namespace candela, none of the engine's inner namespaces or third-party code).
#   tests/install/check-api.sh SOURCE_DIR LIBRARY    (ctest: api.surface)
set -euo pipefail
source=$(cd "$1" && pwd)
library=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cxx=${CXX:-c++}

headers=("$source"/include/candela/*.h)
for header in "${headers[@]}"; do
  name=candela/$(basename "$header")
  echo "#include <$name>" > "$tmp/tu.cpp"
  "$cxx" -std=c++20 -Wall -Wextra -Werror -pedantic -fsyntax-only -I "$source/include" "$tmp/tu.cpp" ||
    fail "$name does not compile alone"
  "$cxx" -std=c++20 -M -I "$source/include" "$tmp/tu.cpp" | tr -s ' \\' '\n' | grep '^/' | sort -u |
    grep -v -e "^$source/include/candela/" -e "^$tmp/" >> "$tmp/reached" || true
done
sort -u "$tmp/reached" -o "$tmp/reached"
# The owners of every other header reached: the compiler's and the C library's packages only.
xargs -a "$tmp/reached" realpath > "$tmp/real"
unowned=$(xargs -a "$tmp/real" dpkg -S 2>&1 >/dev/null | sed -n 's/^dpkg-query: no path found matching pattern //p')
[ -z "$unowned" ] || fail "the public headers reach headers of no package: $unowned"
owners=$(xargs -a "$tmp/real" dpkg -S | cut -d: -f1 | tr ', ' '\n\n' | grep . | sort -u)
for owner in $owners; do
  [[ $owner =~ ^(libstdc\+\+-[0-9]+-dev|libgcc-[0-9]+-dev|libc6-dev|linux-libc-dev)$ ]] ||
    fail "the public headers reach a header of $owner: $(xargs -a "$tmp/real" dpkg -S | grep "^$owner" | head -3)"
done
[ "$(wc -l < "$tmp/reached")" -gt 0 ] || fail "no standard header reached: the -M listing is broken"
echo "${#headers[@]} headers compile alone; they reach $(wc -l < "$tmp/reached") standard headers ($(echo $owners))"

# The exported symbols: the API's classes and functions and their type information, and the weak
# instantiations of standard-library templates its code uses (namespace std has default
# visibility: every C++ library exports those, and the dynamic linker folds them into one).
nm -D --defined-only "$library" | c++filt | sed -E 's/^[0-9a-f]+ //' |
  grep -Ev '^[WVu] ((typeinfo|typeinfo name|vtable) for )?(std::|__gnu_cxx::|void std::|std::__cxx11::basic_string<[^>]*>[^ ]* (std|__gnu_cxx)::)' |
  cut -d' ' -f2- > "$tmp/symbols"
public='^(candela::(version|bytesPerPixel|writeImage|lookAt|sequenceFrame|sphereViews|ringViews|transformsJson|outputName|outputsNamed|allOutputs|outputChannels|outputFiles)(\[abi:cxx11\])?\(|candela::(Device|Scene|Environment|Error|InputError|DeviceError|DeviceLostError|OutOfMemoryError|CancelledError|InternalFailure)::|(typeinfo|typeinfo name|vtable) for candela::(Error|InputError|DeviceError|DeviceLostError|OutOfMemoryError|CancelledError|InternalFailure)$)'
others=$(grep -Ev "$public" "$tmp/symbols" || true)
[ -z "$others" ] || fail "libcandela.so exports more than the API: $(echo "$others" | head -5)"
grep -q "^candela::Device::render(" "$tmp/symbols" || fail "libcandela.so does not export candela::Device::render"
echo "$(wc -l < "$tmp/symbols") symbols exported, all of the API"
echo "ok"
