#!/usr/bin/env bash
# Candela's default framing against <model-viewer>'s (docs/scenes.md, "Framing"): renders each model
# of tests/data/model-viewer/coverage.json at its size (512x512) with the default camera and a
# transparent background, and prints a Markdown table of the share of pixels drawn (alpha > 0) by
# each, with their ratio. Opt-in; model-viewer's figures come from tools/model-viewer/measure.js.
#   tools/framing-coverage.sh [CANDELA] [MODELS_DIR] [OUT_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
candela=${1:-$root/build/release/app/candela}
models=${2:-$root/../shared/assets/models}
out=${3:-$(mktemp -d)}
reference=$root/tests/data/model-viewer/coverage.json
mkdir -p "$out"
/usr/bin/python3 - "$candela" "$models" "$out" "$reference" <<'PY'
import json, subprocess, sys
import numpy as np
candela, models, out, reference = sys.argv[1:]
ref = json.load(open(reference))
print("| model | model-viewer %s | Candela | ratio |" % ref["modelViewerVersion"])
print("|---|---|---|---|")
for name, m in ref["models"].items():
    stem = f"{out}/{name}"
    subprocess.run([candela, "render", "--scene", f"{models}/{m['file']}", "--width", str(ref["width"]), "--height",
                    str(ref["height"]), "--background", "transparent", "--outputs", "color,alpha", "--quiet",
                    "--out", stem + ".png"], check=True, stdout=subprocess.DEVNULL)
    covered = float((np.load(stem + ".alpha.npy") > 0).mean())
    kind = " (animated)" if m.get("animated") else ""
    print(f"| {name}{kind} | {100 * m['coverage']:.1f}% | {100 * covered:.1f}% | {covered / m['coverage']:.2f} |")
PY
