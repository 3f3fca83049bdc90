#!/usr/bin/env python3
"""The Khronos glTF-Validator as an oracle for Candela's glTF loader (docs/robustness.md).

Runs the validator (npm gltf-validator, installed once into BUILD/validator) and `candela render`
(one batch run, 32x32, no environment) over every glTF/GLB file of the shared samples, of the test
scenes and of the bad-input catalogue (written by the cli test binary's
CatalogueFiles.DISABLED_WriteEveryRowsFiles), joins the two outcomes per file and checks them:

  - a file the validator calls valid renders without an error;
  - a file with validator errors fails in Candela with a one-line error, unless every error code is
    one Candela renders through for a stated reason (RENDERS_THROUGH);
  - a catalogue file the validator accepts and Candela refuses belongs to a class of input the
    validator does not check, stated per catalogue class (STRICTER).

Writes OUT/table.md (one row per file) and OUT/summary.md, with --doc the page docs/validator-table.md
(the summary and the table), prints the disagreements, and exits 1 when there is one.

    tools/validator/oracle.py [--build build/release] [--samples ../shared/assets] [--out DIR] [--doc FILE]
"""

import argparse
import collections
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

VALIDATOR_VERSION = "2.0.0-dev.3.10"

# Validator error codes Candela renders through, and why (the file still shows what it means).
RENDERS_THROUGH = {
    "ACCESSOR_MIN_MISMATCH": "bounds come from the vertices, not from accessor.min",
    "ACCESSOR_MAX_MISMATCH": "bounds come from the vertices, not from accessor.max",
    "MESH_PRIMITIVE_POSITION_ACCESSOR_WITHOUT_BOUNDS": "bounds come from the vertices, not from accessor.min/max",
    "ACCESSOR_ELEMENT_OUT_OF_MAX_BOUND": "bounds come from the vertices, not from accessor.max",
    "ACCESSOR_ELEMENT_OUT_OF_MIN_BOUND": "bounds come from the vertices, not from accessor.min",
    "ACCESSOR_NON_UNIT": "normals and tangents are normalized where they are used",
    "ACCESSOR_INVALID_SIGN": "the tangent's w is taken as its sign",
    "ACCESSOR_WEIGHTS_NON_NORMALIZED": "skin weights are renormalized, with a warning",
    "UNDECLARED_EXTENSION": "an extension's properties are read where they are, listed in extensionsUsed or not",
    "EMPTY_ENTITY": "an empty scene draws nothing, with a warning",
    "MESH_PRIMITIVE_NO_TANGENT_SPACE": "tangents are generated where a material needs them (MikkTSpace)",
    "ACCESSOR_VECTOR3_NON_UNIT": "normals and tangents are normalized where they are used",
    "ACCESSOR_INVALID_FLOAT": "non-finite normals and texture coordinates are replaced by the default, with a warning "
                              "(non-finite positions are refused)",
    "ACCESSOR_ANIMATION_INPUT_NON_INCREASING": "repeated key times play as a step (decreasing ones are refused)",
    "ANIMATION_SAMPLER_INPUT_ACCESSOR_WITHOUT_BOUNDS": "an animation's length comes from its keys, not accessor.min/max",
    "GLB_CHUNK_LENGTH_UNALIGNED": "an unpadded GLB chunk is read as its length says, with a warning",
}

# Catalogue classes (the row's folder up to "_") of inputs the validator does not check, which
# Candela refuses with a one-line error.
STRICTER = {
    "truncated": "an image payload the validator does not decode",
    "wrongmagic": "an image payload the validator does not decode",
    "unknownvalue": "a KTX2 payload the validator does not decode",
    "chunklength": "a KTX2 payload the validator does not decode",
    "absurdsize": "Candela's image limits (16384 pixels a side, levels a size can have)",
    "decompressionbomb": "Candela's decoded-size limits, checked from the headers before decoding",
    "URIescapes": "Candela reads no file outside the model's folder",
    "NaNInf": "values beyond single precision, which Candela renders in",
    "animation": "an interpolation Candela cannot play (the validator does not call an unknown one an error)",
    "instancing": "EXT_mesh_gpu_instancing, which the validator does not check",
}


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, text=True, **kw)


def install_validator(build):
    folder = build / "validator"
    if not (folder / "node_modules" / "gltf-validator").is_dir():
        folder.mkdir(parents=True, exist_ok=True)
        run(["npm", "install", "--silent", "--prefix", str(folder), "gltf-validator@" + VALIDATOR_VERSION],
            stdout=subprocess.DEVNULL)
    return folder / "node_modules"


def gltf_files(root):
    return sorted(str(p) for p in pathlib.Path(root).rglob("*") if p.suffix in (".gltf", ".glb") and p.is_file())


def main():
    repo = pathlib.Path(__file__).resolve().parents[2]
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=str(repo / "build" / "release"))
    parser.add_argument("--samples", default=str(repo.parent / "shared" / "assets"))
    parser.add_argument("--out", default=None)
    parser.add_argument("--doc", default=None, help="also write the markdown page (docs/validator-table.md)")
    args = parser.parse_args()
    for tool in ("node", "npm"):
        if not shutil.which(tool):
            sys.exit("oracle: %s is needed to run the glTF-Validator (Node.js and npm)" % tool)
    build = pathlib.Path(args.build).resolve()
    out = pathlib.Path(args.out or tempfile.mkdtemp(prefix="candela_validator_")).resolve()
    out.mkdir(parents=True, exist_ok=True)

    # The inputs: samples, test scenes, the catalogue's glTF/GLB files.
    sources = {}  # file -> "sample", "test scene" or "catalogue"
    models = pathlib.Path(args.samples) / "models"
    if not models.is_dir():
        sys.exit("oracle: no shared samples at %s (--samples)" % models)
    for f in gltf_files(models):
        sources[f] = "sample"
    for f in gltf_files(repo / "assets" / "test-scenes"):
        sources[f] = "test scene"
    catalogue = out / "catalogue"
    shutil.rmtree(catalogue, ignore_errors=True)
    catalogue.mkdir()
    run([str(build / "tests" / "cli" / "candela_cli_tests"), "--gtest_also_run_disabled_tests",
         "--gtest_filter=CatalogueFiles.DISABLED_WriteEveryRowsFiles"],
        env=dict(os.environ, CANDELA_CATALOGUE_DUMP=str(catalogue)), stdout=subprocess.DEVNULL)
    for line in (catalogue / "manifest.tsv").read_text().splitlines():
        folder, name = line.split("\t")[:2]
        f = str(catalogue / folder / name)
        if f.endswith((".gltf", ".glb")):
            sources[f] = "catalogue"
    files = sorted(sources)
    listing = out / "files.txt"
    listing.write_text("".join(f + "\n" for f in files))

    # The validator.
    modules = install_validator(build)
    validated = run(["node", str(repo / "tools" / "validator" / "validate.js"), "@" + str(listing)],
                    env=dict(os.environ, NODE_PATH=str(modules)), stdout=subprocess.PIPE).stdout
    validator = {}
    for line in validated.splitlines():
        r = json.loads(line)
        validator[r["file"]] = r

    # Candela: one batch run, each file on its own (a failure is reported and the run goes on).
    report = out / "report.json"
    subprocess.run([str(build / "app" / "candela"), "render", "@" + str(listing), "--width", "32", "--height", "32",
                    "--env", "none", "--out", str(out / "images" / "{path}.png"), "--report", str(report),
                    "--quiet"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    candela = {}
    for scene in json.loads(report.read_text())["scenes"]:
        candela[scene["file"]] = scene

    rows, disagreements = [], []
    counts = collections.Counter()
    by_group = collections.Counter()
    for f in files:
        group = sources[f]
        kind = os.path.relpath(f, catalogue).split("_")[0] if group == "catalogue" else ""
        v, c = validator.get(f, {}), candela.get(f)
        errors = v.get("errors")
        codes = sorted(k[2:] for k in v.get("codes", {}) if k.startswith("E:"))
        failed = c is None or c.get("status") != "ok"
        ours = ("error: " + c.get("error", "")) if c and failed else ("not rendered" if c is None else
               "renders" + (" (%d warnings)" % len(c.get("warnings", [])) if c.get("warnings") else ""))
        if errors is None and failed and "failed" in v:
            verdict = "agree: both refuse (the validator cannot read it)"
        elif errors is None:
            verdict = "DISAGREE: the validator did not run (%s)" % v.get("failed", "no output")
        elif errors == 0 and not failed:
            verdict = "agree: valid, renders"
        elif errors > 0 and failed:
            verdict = "agree: both refuse"
        elif errors > 0 and all(code in RENDERS_THROUGH for code in codes):
            verdict = "renders through: " + "; ".join(sorted({RENDERS_THROUGH[code] for code in codes}))
        elif errors == 0 and failed and group == "catalogue" and kind in STRICTER:
            verdict = "Candela stricter: " + STRICTER[kind]
        else:
            verdict = "DISAGREE"
        counts[verdict.split(":")[0]] += 1
        by_group[(group, verdict.split(":")[0])] += 1
        name = os.path.relpath(f, models) if group == "sample" else (
            os.path.relpath(f, repo) if group == "test scene" else "catalogue/" + os.path.relpath(f, catalogue))
        validator_text = ("cannot read it" if "failed" in v else "?") if errors is None else "%d errors%s, %d warnings" % (
            errors, (" (" + ", ".join(codes) + ")") if codes else "", v.get("warnings", 0))
        rows.append("| %s | %s | %s | %s |" % (name, validator_text, ours.replace("|", "\\|").replace(f, "FILE"),
                                                 verdict))
        if verdict.startswith("DISAGREE"):
            disagreements.append("%s: validator %s; candela %s; %s" % (
                f, validator_text, ours, "; ".join(v.get("errorMessages", []))))

    (out / "table.md").write_text("| file | glTF-Validator | Candela | verdict |\n|---|---|---|---|\n" + "\n".join(rows) + "\n")
    summary = ", ".join("%s %d" % (k, n) for k, n in sorted(counts.items()))
    groups = "; ".join("%s: %s" % (g, ", ".join("%s %d" % (k, n) for (gg, k), n in sorted(by_group.items()) if gg == g))
                       for g in ("sample", "test scene", "catalogue"))
    (out / "summary.md").write_text("%d files (%s); %s\n" % (len(files), summary, groups))
    if args.doc:
        pathlib.Path(args.doc).write_text(
            "# The glTF-Validator beside Candela, file by file\n\n"
            "Written by `tools/validator/oracle.py --doc docs/validator-table.md` (glTF-Validator %s; what it checks and "
            "why: [robustness.md](robustness.md#the-gltf-validator-as-an-oracle)). Every glTF/GLB file of the shared "
            "samples (`models/…`), the test scenes (`assets/test-scenes/…`) and the bad-input catalogue "
            "(`catalogue/ROW/…`, written by `tests/cli/file_catalogue_test.cpp`): the validator's errors (codes) and "
            "warnings, what `candela render` did (its error line, FILE for the file's path; or its warning count), and "
            "the verdict.\n\n%d files: %s (%s).\n\n" % (VALIDATOR_VERSION, len(files), summary, groups)
            + (out / "table.md").read_text())
    print("oracle: %d files: %s (%s); table in %s" % (len(files), summary, groups, out / "table.md"))
    for d in disagreements:
        print("DISAGREE " + d)
    return 1 if disagreements else 0


if __name__ == "__main__":
    sys.exit(main())
