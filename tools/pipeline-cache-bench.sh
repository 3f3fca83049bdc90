#!/usr/bin/env bash
# First-frame and debug-view-switch times (`candela bench`: firstFrame, debugViewSwitch) over
# --precompile off|frame|debug-views × the pipeline cache cold (an empty folder) or warm (the file
# of an earlier run present), alternated for ROUNDS rounds; each figure also as a ratio to the
# calibration pass of the same run (absolute times on a shared CPU vary up to 2x). Holds
# /tmp/candela-build.lock around each run when it exists, so that builds do not run meanwhile.
#
#   tools/pipeline-cache-bench.sh ROUNDS CANDELA [SCENE FLAGS...]    e.g. 4 build/release/app/candela --grid 7 --env none
set -euo pipefail
rounds=$1; bin=$2; shift 2
cache=$(mktemp -d)
trap 'rm -rf "$cache"' EXIT
lock=(); [ -e /tmp/candela-build.lock ] && lock=(flock /tmp/candela-build.lock)
for r in $(seq "$rounds"); do
  for pre in off frame debug-views; do
    for state in cold warm; do
      [ "$state" = cold ] && rm -rf "$cache/pc"
      [ "$state" = warm ] && [ ! -e "$cache/pc" ] && "$bin" bench "$@" --frames 1 --pipeline-cache "$cache/pc" >/dev/null 2>&1
      "${lock[@]}" "$bin" bench "$@" --frames 8 --precompile "$pre" --pipeline-cache "$cache/pc" --json 2>/dev/null |
        /usr/bin/python3 -c "
import json, sys
d = json.load(sys.stdin); f = d['firstFrame']; s = d['debugViewSwitch']
print('$r $pre $state first %.1f ms %.2fx  switch %.1f ms %.2fx  next %.2fx  frame %.2fx  cal %.1f ms' % (
    f['ms'], f['ratio'], s['firstMs'], s['firstRatio'], s['nextRatio'], d['frame']['medianRatio'], d['calibration']['medianMs']))"
    done
  done
done
