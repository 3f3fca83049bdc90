#!/usr/bin/env bash
# The GPU check: runs from the relocatable tarball (docs/packaging.md; `cpack -G TGZ -D
# CANDELA_GPU_CHECK=ON` adds the GPU test binary, the validation layer and what the tests read) on a
# machine with a Vulkan driver and writes one report, OUT/report.md, with the files it summarizes
# beside it:
#   1. `candela info` under the validation layer: the devices, the one chosen, the features
#   2. the golden scenes (tests/gpu/golden_test.cpp) through both shading paths under validation,
#      every render kept, compared with the approved lavapipe images by ꟻLIP (`candela diff`)
#   3. 1280x720 renders of the default scene and DamagedHelmet on both paths, under validation
#   4. `candela bench` of DamagedHelmet and the 10x10 grid (as ratios to the calibration pass)
#   5. time to image: `candela bench --cold` (fresh processes, from process start to the PNG written,
#      the first with empty caches) of the default scene and DamagedHelmet,
#      a `render --verbose` breakdown of the helmet, and the assets' models at 512x512 in one run
#   6. the rest of the GPU test binary, if the tarball has it (every test under validation)
# Steps 2 and 6 need the GPU test binary; without the validation layer in the tarball (the plain
# one) every step runs without validation, which the report says.
#   ./gpu-check.sh [--assets DIR] [--out DIR] [--tests-timeout SECONDS]
#                  [--golden-filter GTEST_PATTERN] [--tests-filter GTEST_PATTERN] [--bench-frames N]
#                  [--cold-runs N]
# --assets: the shared sample assets (models/, environments/); without them the golden cases of
# sample models are skipped, the helmet is not rendered or benched and no batch runs. The filters,
# the frame count and the cold runs narrow the run (its own test, tests/cli/gpu_check_test.sh, runs one golden case and one
# test). The machine's Vulkan driver must be found by the loader (VK_DRIVER_FILES may name its
# manifest).
# Exit status 0 when every step ran (failed tests and golden differences are in the report: a
# GPU's images differ from lavapipe's within what the report shows), 1 when a step could not run.
set -uo pipefail
bundle=$(cd "$(dirname "$0")" && pwd)
assets="" out=$PWD/gpu-check tests_timeout=900 golden_filter='*' tests_filter='*' bench_frames=100 cold_runs=10
while [ $# -gt 0 ]; do
  case $1 in
    --assets) assets=$(cd "$2" && pwd) || exit 1; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --tests-timeout) tests_timeout=$2; shift 2 ;;
    --golden-filter) golden_filter=$2; shift 2 ;;
    --tests-filter) tests_filter=$2; shift 2 ;;
    --bench-frames) bench_frames=$2; shift 2 ;;
    --cold-runs) cold_runs=$2; shift 2 ;;
    *) echo "usage: gpu-check.sh [--assets DIR] [--out DIR] [--tests-timeout SECONDS] [--golden-filter PATTERN]" \
         "[--tests-filter PATTERN] [--bench-frames N] [--cold-runs N]" >&2; exit 2 ;;
  esac
done
mkdir -p "$out" && out=$(cd "$out" && pwd)
# The programs find the tarball's libraries by their run path ($ORIGIN/../lib); the loader finds
# the tarball's validation layer here.
validate=""
if [ -f "$bundle/lib/vulkan/explicit_layer.d/VkLayer_khronos_validation.json" ]; then
  export VK_LAYER_PATH=$bundle/lib/vulkan/explicit_layer.d
  validate=--validate
fi
export CANDELA_GOLDEN_DIR=$bundle/share/candela/golden
export CANDELA_TEST_DATA=$bundle/share/candela/test-data
export CANDELA_TEST_SCENES=$bundle/share/candela/test-scenes
export CANDELA_GOLDEN_OUT=$out/golden
export CANDELA_SHARED_ASSETS=${assets:-$out/no-assets}
candela=$bundle/bin/candela
tests=$bundle/bin/candela_gpu_tests
status=0
step() { echo "== $*" >&2; }
timed() {  # NAME COMMAND...: runs COMMAND, its output in OUT/NAME.log, its seconds in OUT/NAME.seconds
  local name=$1 start rc; shift
  start=$(date +%s.%N)
  "$@" > "$out/$name.log" 2>&1; rc=$?
  awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {printf "%.2f\n", b - a}' > "$out/$name.seconds"
  echo "$rc" > "$out/$name.rc"
  return $rc
}

{
  echo "commit: $(cat "$bundle/share/candela/commit" 2>/dev/null || echo unknown)"
  echo "date: $(date -u +%FT%TZ)"
  echo "kernel: $(uname -srm)"
  if [ -n "$validate" ]; then echo "validation: on (the layer in the tarball, with synchronization validation)"
  else echo "validation: off (no validation layer in the tarball)"; fi
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //') ($(nproc) threads)"
  command -v nvidia-smi > /dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | sed 's/^/gpu: /'
} > "$out/machine.txt"

step "info"
timed info "$candela" info $validate || status=1

step "golden scenes, both shading paths"
if [ -x "$tests" ]; then
  rm -rf "$out/golden"
  CANDELA_GOLDEN_KEEP=1 timed golden "$tests" --gtest_filter="*GoldenTest.*$golden_filter" --gtest_output=xml:"$out/golden.xml"
  mkdir -p "$out/golden-forward" "$out/golden-visibility"
  for f in "$out"/golden/*.actual.png; do [ -e "$f" ] && cp "$f" "$out/golden-forward/$(basename "$f" .actual.png).png"; done
  for f in "$out"/golden/*.visibility.png; do [ -e "$f" ] && cp "$f" "$out/golden-visibility/$(basename "$f" .visibility.png).png"; done
  for path in forward visibility; do
    "$candela" diff "$bundle/share/candela/golden" "$out/golden-$path" --report "$out/flip-$path.json" \
      > "$out/flip-$path.log" 2>&1
  done
else
  echo "no GPU test binary in the tarball" > "$out/golden.log"
fi

step "renders"
helmet=""
[ -n "$assets" ] && helmet=$assets/models/DamagedHelmet/glTF-Binary/DamagedHelmet.glb
for path in forward visibility; do
  timed "render-default-$path" "$candela" render $validate --shading-path "$path" --out "$out/default-$path.png" || status=1
  if [ -f "$helmet" ]; then
    timed "render-helmet-$path" "$candela" render $validate --shading-path "$path" --scene "$helmet" \
      --out "$out/helmet-$path.png" || status=1
  fi
done

step "repeated frames"
# A still scene drawn 3 frames in a row (each frame in flight has its own per-frame resources)
# must give 3 identical images. A write that a barrier does not make visible to a later read, or a
# resource read before anything wrote it, shows here on a GPU (its caches, memory that is not
# zero), not on lavapipe, whose memory is coherent.
for path in forward visibility; do
  for msaa in 1 4; do
    name=frames-$path-msaa$msaa
    timed "$name" "$candela" render $validate --shading-path "$path" --msaa "$msaa" --width 640 --height 360 \
      --frames 3 --out "$out/$name-%d.png" || status=1
    for i in 1 2; do
      "$candela" diff "$out/$name-0.png" "$out/$name-$i.png" > "$out/$name-0-$i.diff" 2>&1
    done
  done
done

step "bench"
timed bench-grid "$candela" bench --grid 10 --width 1280 --height 720 --frames "$bench_frames" --json || status=1
if [ -f "$helmet" ]; then
  timed bench-helmet "$candela" bench --scene "$helmet" --width 1280 --height 720 --frames "$bench_frames" --json || status=1
fi

step "time to image"
# Without validation: the time a user waits. Each bench starts with empty pipeline, environment and
# level-of-detail caches (a folder of their own), so its first run is a cold start and the rest warm;
# the helmet's breakdown and the batch then find the helmet's caches.
export XDG_CACHE_HOME=$out/cache
rm -rf "$XDG_CACHE_HOME"
# bench's JSON in a file of its own (OUT/cold-*.json), its messages in the log.
timed cold-default sh -c '"$0" bench --cold "$1" --json > "$2"' "$candela" "$cold_runs" "$out/cold-default.json" || status=1
rm -rf "$XDG_CACHE_HOME"
if [ -f "$helmet" ]; then
  timed cold-helmet sh -c '"$0" bench --cold "$1" --scene "$2" --json > "$3"' "$candela" "$cold_runs" "$helmet" \
    "$out/cold-helmet.json" || status=1
  timed ttfi-helmet "$candela" render --scene "$helmet" --out "$out/ttfi-helmet.png" --verbose || status=1
  rm -rf "$out/batch"
  timed batch "$candela" render "$assets/models" --width 512 --height 512 --out "$out/batch/{path}.png" --quiet || status=1
  find "$out/batch" -name '*.png' | wc -l > "$out/batch.files"
  rm -rf "$out/batch" "$XDG_CACHE_HOME"
fi
unset XDG_CACHE_HOME

step "GPU tests"
# In 4 processes (gtest's sharding): a crash ends one share, not the run.
if [ -x "$tests" ]; then
  for shard in 0 1 2 3; do
    GTEST_TOTAL_SHARDS=4 GTEST_SHARD_INDEX=$shard timed "gpu-tests-$shard" timeout "$tests_timeout" "$tests" \
      --gtest_filter="$tests_filter-*GoldenTest.*" --gtest_output=xml:"$out/gpu-tests-$shard.xml" &
  done
  wait
fi

step "report"
python3 - "$out" > "$out/report.md" <<'EOF' || status=1
import json, os, re, sys, xml.etree.ElementTree as ET
out = sys.argv[1]
def text(name, default=""):
    path = os.path.join(out, name)
    return open(path, errors="replace").read() if os.path.exists(path) else default
def seconds(name):
    return float(text(name + ".seconds", "nan") or "nan")
print("# GPU check\n")
print("```\n" + text("machine.txt").strip() + "\n```\n")
print("## Device (`candela info`, exit %s)\n" % text("info.rc", "?").strip())
print("```\n" + text("info.log").strip() + "\n```\n")

def tests(name):
    """gtest results of OUT/NAME.xml, or of NAME.log's status lines when the run left no XML."""
    result = {"run": 0, "skipped": 0, "failed": [], "seconds": seconds(name), "rc": text(name + ".rc", "?").strip(),
              "from": "xml"}
    path = os.path.join(out, name + ".xml")
    if os.path.exists(path):
        for c in ET.parse(path).getroot().iter("testcase"):
            if c.get("result") == "skipped" or c.find("skipped") is not None:
                result["skipped"] += 1
                continue
            result["run"] += 1
            failures = c.findall("failure")
            if failures:
                message = failures[0].get("message", "").splitlines()
                result["failed"].append((c.get("classname") + "." + c.get("name"), " | ".join(message[:3])[:300]))
        return result
    log = text(name + ".log")
    if not log:
        return None
    result["from"] = "log"
    for line in log.splitlines():
        m = re.match(r"\[ +(OK|FAILED|SKIPPED) +\] (\S+) \(", line)
        if not m:
            continue
        if m.group(1) == "SKIPPED":
            result["skipped"] += 1
        else:
            result["run"] += 1
            if m.group(1) == "FAILED":
                result["failed"].append((m.group(2), "see %s.log" % name))
    result["last"] = log.strip().splitlines()[-3:]
    return result

def show_tests(title, names):
    print("## %s\n" % title)
    for name in names:
        r = tests(name)
        if r is None:
            print("- %s: not run\n" % name)
            continue
        print("- %s: %d run, %d passed, %d failed, %d skipped; %.0f s, exit %s%s" % (
            name, r["run"], r["run"] - len(r["failed"]), len(r["failed"]), r["skipped"], r["seconds"], r["rc"],
            "" if r["from"] == "xml" else " (no XML: counted from the log; it ends: %s)" % " / ".join(r["last"])))
        for test, message in r["failed"]:
            print("  - `%s`: %s" % (test, message))
    print()

show_tests("Golden tests (lavapipe's tolerances)", ["golden"])
print("## Golden scenes against the approved images, ꟻLIP\n")
for path in ("forward", "visibility"):
    report = os.path.join(out, "flip-%s.json" % path)
    if not os.path.exists(report):
        print("%s: no comparison\n" % path)
        continue
    data = json.load(open(report))
    pairs = data.get("pairs", [])
    missing = [p["name"] for p in pairs if p.get("status") == "missing"]
    compared = [p for p in pairs if p.get("flip")]
    print("### %s path: %d images compared, %d without a render (asset absent)\n" % (path, len(compared), len(missing)))
    print("| image | mean ꟻLIP | max ꟻLIP | PSNR dB | max channel difference | share over 5 levels |")
    print("|---|---|---|---|---|---|")
    for p in sorted(compared, key=lambda p: -p["flip"]["mean"]):
        psnr = "inf" if p.get("psnr") is None else "%.2f" % p["psnr"]
        print("| %s | %.4f | %.4f | %s | %d | %.3f%% |" % (p["name"], p["flip"]["mean"], p["flip"]["max"], psnr,
                                                       p["maxChannelDifference"], 100 * p["fractionOverThreshold"]))
    print()

print("## Renders (1280x720)\n")
for name in sorted(f[:-4] for f in os.listdir(out) if f.startswith("render-") and f.endswith(".log")):
    log = text(name + ".log").strip().splitlines()
    print("- %s: exit %s, %.1f s%s" % (name, text(name + ".rc", "?").strip(), seconds(name),
                                     ("; " + " / ".join(log[-3:])) if text(name + ".rc").strip() != "0" else ""))
print()
print("## Repeated frames of a still scene (640x360, 3 frames; frame 0 against 1 and 2)\n")
for name in sorted(f[:-4] for f in os.listdir(out) if f.startswith("frames-") and f.endswith(".log")):
    lines = []
    for i in (1, 2):
        first = text("%s-0-%d.diff" % (name, i)).strip().splitlines()
        lines.append(first[0] if first else "no comparison")
    print("- %s (exit %s): %s" % (name, text(name + ".rc", "?").strip(), " / ".join(lines)))
print()
print("## Bench (1280x720)\n")
print("| scene | frame median | ratio to calibration | GPU passes |")
print("|---|---|---|---|")
for scene in ("helmet", "grid"):
    try:
        b = json.loads(text("bench-%s.log" % scene))
    except ValueError:
        if os.path.exists(os.path.join(out, "bench-%s.log" % scene)):
            print("| %s | failed: %s | | |" % (scene, text("bench-%s.log" % scene).strip().splitlines()[-1:]))
        continue
    passes = ", ".join("%s %.3f ms" % (p["name"], p.get("gpuMedianMs", 0.0)) for p in b.get("passes", []))
    print("| %s | %.3f ms | %.2fx | %s |" % (os.path.basename(b["scene"]), b["frame"]["medianMs"], b["frame"]["medianRatio"], passes))
print()
print("## Time to image (no validation; process start to the PNG written)\n")
print("| scene | first run (caches empty) | warm median | warm min | warm / calibration |")
print("|---|---|---|---|---|")
for scene in ("default", "helmet"):
    if not os.path.exists(os.path.join(out, "cold-%s.log" % scene)):
        continue
    try:
        c = json.loads(text("cold-%s.json" % scene))
        print("| %s | %.0f ms | %.0f ms | %.0f ms | %.1fx |" % (scene, c["firstMs"], c["warmMedianMs"], c["warmMinMs"],
                                                              c["warmRatio"]))
    except (ValueError, KeyError, TypeError):  # no JSON, or one run only (no warm runs)
        last = text("cold-%s.log" % scene).strip().splitlines()[-1:]
        print("| %s | exit %s%s | | | |" % (scene, text("cold-%s.rc" % scene, "?").strip(), (": " + last[0]) if last else ""))
print()
breakdown = [l for l in text("ttfi-helmet.log").splitlines() if "time to image" in l]
if breakdown:
    print("DamagedHelmet, `render --verbose` (caches warm):\n\n```\n" + "\n".join(breakdown) + "\n```\n")
if os.path.exists(os.path.join(out, "batch.seconds")):
    print("The assets' models at 512x512 in one run: %s files, %.1f s, exit %s\n" % (
        text("batch.files", "?").strip(), seconds("batch"), text("batch.rc", "?").strip()))
show_tests("GPU tests (every test but the goldens, under validation; 4 shares)", ["gpu-tests-%d" % i for i in range(4)])
EOF
echo "report: $out/report.md" >&2
exit $status
