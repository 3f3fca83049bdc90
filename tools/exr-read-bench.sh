#!/usr/bin/env bash
# EXR read times: Candela's OpenEXR reader against tinyexr 1.0.1, the reader it replaced, on the
# shared environments re-encoded as EXR and a 4096 x 2048 float map (tools/bench/exr_read_bench.cpp).
# Needs Debian's libtinyexr-dev for the comparison (installed here if missing and root).
#
#   tools/exr-read-bench.sh [ROUNDS]        default 7; inputs are written to build/exr-read-bench/
set -euo pipefail
cd "$(dirname "$0")/.."
if ! dpkg-query -W -f='${Status}' libtinyexr-dev 2>/dev/null | grep -q "install ok installed"; then
  [ "$(id -u)" -eq 0 ] || { echo "error: install libtinyexr-dev (the baseline) first" >&2; exit 1; }
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends libtinyexr-dev >/dev/null
fi
cmake --preset release >/dev/null
cmake --build --preset release --target candela_exr_read_bench
build/release/tools/bench/candela_exr_read_bench build/exr-read-bench "${1:-7}" ../shared/assets/environments/*.hdr
