#!/usr/bin/env bash
# Approves golden images: copies renders written by a failing or new golden test
# (BUILD/tests/gpu/golden_out/NAME.actual.png) to tests/golden/NAME.png.
# Look at every image before approving it.
#   tools/approve-goldens.sh [--build DIR] NAME...    approve the named cases
#   tools/approve-goldens.sh [--build DIR] --all      approve every pending render
set -euo pipefail
cd "$(dirname "$0")/.."
build=build/release
if [ "${1:-}" = "--build" ]; then build="$2"; shift 2; fi
out="$build/tests/gpu/golden_out"
[ -d "$out" ] || { echo "error: $out does not exist (run the golden tests first)" >&2; exit 1; }
if [ "${1:-}" = "--all" ]; then
  names=$(cd "$out" && ls *.actual.png 2>/dev/null | sed 's/\.actual\.png$//')
else
  names="$*"
fi
[ -n "$names" ] || { echo "error: nothing to approve" >&2; exit 1; }
for name in $names; do
  src="$out/$name.actual.png"
  [ -f "$src" ] || { echo "error: $src not found" >&2; exit 1; }
  cp "$src" "tests/golden/$name.png"
  echo "approved tests/golden/$name.png"
done
