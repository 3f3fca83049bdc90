#!/usr/bin/env python3
"""Checks README.md, CONTRIBUTING.md and docs/*.md against the program and the tree:

- every `candela COMMAND ...` written in them (inline code or a code block, continuation lines
  joined) passes only flags that COMMAND takes, as `candela COMMAND --help` lists them;
- every flag named anywhere in them (`--name`) is a flag of some command, unless it is one of
  another tool's (cmake, ctest, GoogleTest, ...: OTHER_TOOLS_FLAGS);
- every path of the tree named in backticks (starting with app/, engine/, shaders/, tests/,
  tools/, docs/, assets/, .ci/ or a folder of engine/, which the docs name without engine/) exists
  — placeholders (NAME, TARGET: a component in capitals) and patterns (*, {a,b}, …) left aside —
  and every relative Markdown link resolves;
- every size claimed of a file in backticks — "`PATH` (..., under N lines)" or "(`PATH`, ~N
  lines)" — holds: under N, or within 25% of ~N (a glob such as `vk/memory.*` counts its files
  together; a sum such as "~120 + ~180 lines" is left aside);
- docs/architecture.md's claims about passes: each pass its engine/passes table names for a folder
  is declared by a file of that folder, and the pass order its frame diagram draws (the forward
  chain "skin_morph → … → tonemap" and the visibility chain "visibility → … forward_blended]")
  is the order of the passes the executable runs (`--graph-json` of frames in the tree's test
  scenes that run most of them, on both paths); a pass no such frame runs must at least be a pass
  name the engine declares.

Usage: check_docs.py PROJECT_DIR CANDELA_EXECUTABLE. Prints one line per problem (FILE:LINE: what)
and exits 1 when there is one. Registered with ctest as `docs` (tests/cli/CMakeLists.txt).
"""
import glob
import os
import re
import subprocess
import sys

COMMANDS = ["render", "view", "bench", "ibl-report", "scale-report", "quality-report", "diff", "soak", "info"]
# Flags of other tools that the docs quote in their own command lines.
OTHER_TOOLS_FLAGS = {"--preset", "--build", "--install", "--prefix", "--test-dir", "--target", "--target-env", "--gtest_filter", "--array",
                     "--basisu", "--gtest_brief",
                     "--write-docs",  # tools/check_layers.py's
                     "--assets", "--cold-runs",  # tools/gpu-check.sh's
                     "--size",  # tools/python-overhead.py's
                     "--doc", "--samples",  # tools/validator/oracle.py's
                     "--set-spec-const-default-value", "--freeze-spec-const", "--fold-spec-const-op-composite",  # spirv-opt's
                     "--scen"}  # the README's example of a mistyped flag and its error
TREE_ROOTS = ("app/", "engine/", "shaders/", "tests/", "tools/", "docs/", "assets/", ".ci/")
FLAG = re.compile(r"(?<![\w-])(--[a-z][a-z0-9_-]*)")


def command_flags(executable):
    flags = {}
    for command in COMMANDS:
        text = subprocess.run([executable, command, "--help"], capture_output=True, text=True, check=True).stdout
        flags[command] = set(FLAG.findall(text)) | {"--help"}
    return flags


def line_of(text, offset):
    return text.count("\n", 0, offset) + text.count("\r", 0, offset) + 1


def check_commands(rel, text, flags, problems):
    # A backslash at a line's end continues the command; inline code may wrap across lines. Such
    # line breaks become \r, which a command runs over and line_of still counts.
    joined = text.replace("\\\n", " \r")
    joined = re.sub(r"`[^`]*`", lambda m: m.group(0).replace("\n", "\r"), joined)
    for match in re.finditer(r"candela ([a-z-]+)\b([^`\n#|]*)", joined):
        command, rest = match.group(1), match.group(2)
        if command not in COMMANDS:
            continue
        # Another command line on the same line (a table cell, a sentence) ends this one.
        rest = re.split(r"candela |\s--?\s|;", rest)[0]
        for flag in FLAG.findall(rest):
            if flag not in flags[command] and flag not in OTHER_TOOLS_FLAGS:
                problems.append(f"{rel}:{line_of(joined, match.start())}: candela {command} does not take {flag}")


def check_flags(rel, text, all_flags, problems):
    for number, line in enumerate(text.split("\n"), 1):
        for flag in FLAG.findall(line):
            if flag not in all_flags and flag not in OTHER_TOOLS_FLAGS:
                problems.append(f"{rel}:{number}: {flag} is not a flag of any command")


def check_paths(root, rel, text, problems):
    here = os.path.dirname(rel)
    roots = TREE_ROOTS + tuple(name + "/" for name in os.listdir(os.path.join(root, "engine"))
                               if os.path.isdir(os.path.join(root, "engine", name)))
    exists = lambda pattern: any(glob.glob(os.path.join(root, base, pattern)) for base in ("", "engine"))
    for number, line in enumerate(text.split("\n"), 1):
        for span in re.findall(r"`([^`\s]+)`", line):
            path = span.split("#")[0].rstrip(":,")
            if not path.startswith(roots) or any(c in path for c in "{}…$<>|"):
                continue
            if any(re.match(r"[A-Z]{3,}[A-Z_]*([._]|$)", part) for part in path.split("/")):
                continue  # a placeholder: shaders/NAME.STAGE.glsl, tests/fuzz/regressions/TARGET
            path = re.sub(r":\d+$", "", path)  # file:line
            if not exists(path):  # `x.*` is a file's header and source
                problems.append(f"{rel}:{number}: `{span}` does not exist")
        for link in re.findall(r"\]\(([^)\s]+)\)", line):
            target = link.split("#")[0]
            if not target or re.match(r"[a-z]+:", target):
                continue
            if not os.path.exists(os.path.normpath(os.path.join(root, here, target))):
                problems.append(f"{rel}:{number}: link {link} does not resolve")


SIZE_CLAIM = re.compile(r"`([^`\s]+)`[^`\n+]{0,40}?(\bunder |~)([0-9][0-9,]*) lines")

def check_sizes(root, rel, text, problems):
    for m in SIZE_CLAIM.finditer(text):
        path, kind, claimed = m.group(1), m.group(2).strip(), int(m.group(3).replace(",", ""))
        # A path of the tree, a path under engine/ (the docs name its folders without it), or a
        # bare file name somewhere under engine/.
        base = path if path.startswith(TREE_ROOTS) else "engine/" + path if "/" in path else "engine/**/" + path
        files = sorted(glob.glob(os.path.join(root, base), recursive=True))
        if not files:
            problems.append(f"{rel}:{line_of(text, m.start())}: size claimed of `{path}`, which names no file")
            continue
        lines = 0
        for name in files:
            with open(name, encoding="utf-8") as f:
                lines += sum(1 for _ in f)
        if kind == "under" and lines >= claimed:
            problems.append(f"{rel}:{line_of(text, m.start())}: `{path}` is {lines} lines, not under {claimed}")
        if kind == "~" and not 0.75 * claimed <= lines <= 1.25 * claimed:
            problems.append(f"{rel}:{line_of(text, m.start())}: `{path}` is {lines} lines, not ~{claimed}")


PASS_LITERAL = re.compile(r'"([a-z][a-z0-9_]*)"')


def declared_passes(root, folder="engine/passes/**"):
    """The string literals of the .cpp files under `folder`: a superset of the pass names declared there."""
    names = set()
    for path in glob.glob(os.path.join(root, folder, "*.cpp"), recursive=True):
        with open(path, encoding="utf-8") as f:
            names |= set(PASS_LITERAL.findall(f.read()))
    return names


def ran_passes(root, executable, args):
    """The passes a frame of `candela render ARGS` ran, in the order they ran."""
    import json
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        graph = os.path.join(tmp, "graph.json")
        subprocess.run([executable, "render", "--width", "64", "--height", "36", "--quiet", "--out",
                        os.path.join(tmp, "frame.png"), "--graph-json", graph] + args,
                       capture_output=True, text=True, check=True, cwd=root)
        with open(graph, encoding="utf-8") as f:
            passes = json.load(f)["passes"]
    return [p["name"] for p in sorted((p for p in passes if not p["culled"]), key=lambda p: p["order"])]


def check_architecture_passes(root, executable, problems):
    rel = "docs/architecture.md"
    with open(os.path.join(root, rel), encoding="utf-8") as f:
        text = f.read()
    # The engine/passes table: a folder's row names passes in backticks (identifiers only).
    for m in re.finditer(r"^\| `([a-z]+)/` \| (.*) \|$", text, re.M):
        folder, what = m.group(1), m.group(2)
        literals = declared_passes(root, "engine/passes/" + folder)
        for name in re.findall(r"`([a-z][a-z0-9_]*)`", what):
            if name not in literals:
                problems.append(f"{rel}:{line_of(text, m.start())}: `{name}` is not declared in engine/passes/{folder}/")
    # The frame diagram's chains against the passes frames run.
    scenes = os.path.join(root, "assets", "test-scenes")
    frames = [["--scene", os.path.join(scenes, "DispersionSweep.glb"), "--env", "sky"],
              ["--scene", os.path.join(scenes, "DispersionSweep.glb"), "--env", "sky", "--shading-path", "visibility",
               "--msaa", "4"],
              ["--env", "sky", "--shading-path", "visibility"]]
    small = ["--ibl-cube-size", "32", "--ibl-levels", "4", "--ibl-lut-size", "16"]  # the passes, not the maps
    try:
        runs = [ran_passes(root, executable, args + small) for args in frames]
    except subprocess.CalledProcessError as e:
        problems.append(f"{rel}: checking the frame diagram, {' '.join(e.cmd)} failed: {e.stderr.strip()}")
        return
    seen = set().union(*runs)
    engine = declared_passes(root, "engine/**")
    for pattern in (r"skin_morph →.*?tonemap", r"visibility → visibility_classify.*?forward_blended\]"):
        m = re.search(pattern, text, re.S)
        if not m:
            problems.append(f"{rel}: the frame diagram has no chain matching {pattern}")
            continue
        chain = [t for t in re.findall(r"[a-z][a-z0-9_]*", m.group(0)) if t in engine or t in seen]
        for name in chain:
            if name not in seen and name not in engine:
                problems.append(f"{rel}:{line_of(text, m.start())}: `{name}` in the frame diagram is no pass")
        for args, run in zip(frames, runs):
            ran = [p for p in run if p in chain]
            drawn = [p for p in chain if p in run]
            if ran != drawn:
                problems.append(f"{rel}:{line_of(text, m.start())}: the diagram orders {' → '.join(drawn)}; "
                                f"candela render {' '.join(os.path.basename(a) for a in args)} ran {' → '.join(ran)}")


def main():
    root, executable = sys.argv[1], sys.argv[2]
    flags = command_flags(executable)
    all_flags = set().union(*flags.values()) | {"--version"}
    files = ["README.md", "CONTRIBUTING.md"] + sorted(os.path.relpath(p, root) for p in glob.glob(os.path.join(root, "docs/*.md")))
    problems = []
    for rel in files:
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            text = f.read()
        check_commands(rel, text, flags, problems)
        check_flags(rel, text, all_flags, problems)
        check_paths(root, rel, text, problems)
        check_sizes(root, rel, text, problems)
    check_architecture_passes(root, executable, problems)
    for problem in problems:
        print(problem)
    print(f"{len(files)} files checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
