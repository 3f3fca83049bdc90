#!/usr/bin/env python3
"""Candela's layer check: every #include "..." points down the layer table (engine/layers.txt).

    tools/check_layers.py [ROOT] [--direct] [--no-cmake] [--write-docs]

Reads every quoted #include in engine/, app/, tools/, tests/ and shaders/ (*.h, *.cpp, *.in),
resolves it as the build does (the including file's folder, engine/, shaders/; for app/, tools/ and
tests/ also app/, tests/unit, tests/fuzz), and maps both ends to a layer: a folder of engine/ (a row
of engine/layers.txt), or "shared" for shaders/shared/*.h. Includes that resolve outside engine/
and shaders/shared (test helpers, app-local headers) are not layered.

A file in engine/FOLDER may include its own folder and every folder reachable from it along the
links of the table (what its target links, directly or further down). Anything else fails, one line
per include: "points up" when the included folder depends on the including one, "sideways" when
neither reaches the other. A file outside engine/ is held to the CONSUMERS row its path matches
first (the binary it is compiled into); tests/unit/FOLDER/ (FOLDER a layer) is compiled into
candela_unit_tests when FOLDER's kind is cpu, else into candela_engine_unit_tests, and may include
what that binary links: the layers of its test folders and everything below them. Exit status 1 on
any violation, 0 otherwise.

The layer table's section of docs/architecture.md (between the "layers" markers: the table's
folder, target and links columns, and the levels) must be what --write-docs writes; the job column
is the doc's own.

--direct     also reports includes of a folder that is reachable but not a direct link (informational:
             keeps the table's direct lists honest; never fails the run).
--no-cmake   skips the check that every candela_* library an engine/*/CMakeLists.txt links to a
             layer's target (besides what engine/layers.cmake links from the table) is a direct link
             of the layer's row.
--write-docs rewrites docs/architecture.md's table and levels from engine/layers.txt and exits.

Registered with ctest as `layers` (tests/CMakeLists.txt).
"""
import os
import re
import sys


def read_layers(root):
    """engine/layers.txt as ({folder: (target, kind, direct links)}, {folder: namespace}), in the
    table's order."""
    layers, namespaces = {}, {}
    with open(os.path.join(root, "engine", "layers.txt"), encoding="utf-8") as f:
        for line in f:
            if not re.match(r"[a-z]", line):
                continue
            fields = line.split()
            folder, target, namespace, kind = fields[:4]
            links = [x for x in fields[4:] if x not in ("|", "-")]
            layers[folder] = (target, kind, links)
            namespaces[folder] = namespace
    return layers, namespaces


LAYERS, NAMESPACES, ALL, CPU, CONSUMERS = {}, {}, [], [], []


def load(root):
    """Reads the layer table and derives from it the rules of the files outside engine/."""
    global LAYERS, NAMESPACES, ALL, CPU, CONSUMERS
    LAYERS, NAMESPACES = read_layers(root)
    ALL = list(LAYERS)
    CPU = [f for f, (_, kind, _) in LAYERS.items() if kind == "cpu"]
    tests = os.path.join(root, "tests", "unit")
    cpu_tests = [f for f in CPU if os.path.isdir(os.path.join(tests, f))]
    engine_tests = [f for f in ALL if f not in CPU and os.path.isdir(os.path.join(tests, f))]
    # Files outside engine/: the first row whose path matches (a file, or a folder ending in /):
    # (path, folders it may include (and everything below them))
    CONSUMERS = [
        # candela_cli: the argument parser, tested without the engine (tests/cli), and the manual page
        # and completions written from its tables (candela_cli_docs): the settings chosen by name
        # (options), the IBL settings and the names-table lookups; no device-side layer.
        *[(f"app/{name}", ["ibl", "core", "options", "shared"])
          for name in ["cli.h", "cli.cpp", "cli_commands.cpp", "cli_flags.h", "cli_flags.cpp", "cli_help.cpp",
                       "cli_manual.h", "cli_manual.cpp", "cli_docs_main.cpp",
                       "cli_values.h", "cli_values.cpp", "flag_spec.h", "flag_groups.h", "flag_groups.cpp",
                       "common_options.h", "scene_render_options.h",
                       *[f"{command}_cli.{ext}" for command in ["render", "view", "bench", "ibl_report", "scale_report",
                                                                "quality_report", "soak", "diff", "info"]
                         for ext in ["h", "cpp"]]]],
        ("app/", ALL),
        ("tools/bench/graph_compile_bench.cpp", ["graph"]),
        ("tools/bench/pose_bench.cpp", ["assets", "pose"]),
        ("tools/bench/exr_read_bench.cpp", ["assets"]),
        ("tools/", ALL),
        # tests/unit/FOLDER/ tests engine/FOLDER (tests/unit/CMakeLists.txt): candela_engine_unit_tests
        # holds the device-side and viewer folders (no device created, no window opened) and links
        # their libraries ...
        *[(f"tests/unit/{f}/", engine_tests) for f in engine_tests],
        # ... candela_unit_tests the CPU ones; the helpers at tests/unit's top, shared by every test
        # binary, use the CPU libraries only.
        *[(f"tests/unit/{f}/", CPU) for f in cpu_tests],
        ("tests/unit/", CPU),
        # The fuzz build configures nothing above the readers (and the images `candela diff` reads).
        ("tests/fuzz/", ["assets", "pose", "reports"]),
        ("tests/", ALL),
        # candela_shaders defines shader/builtin_shaders.h.
        ("shaders/", ["shader", "shared"]),
    ]


SCAN = ("engine", "app", "tools", "tests", "shaders", "examples")
SKIP_DIRS = {"build", "regressions", "uri-folder", "golden", ".git"}
EXTS = (".h", ".cpp", ".in")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def reach(folder):
    """Folders reachable from `folder` along the table's links (without itself)."""
    seen, todo = set(), list(LAYERS[folder][2])
    while todo:
        f = todo.pop()
        if f not in seen:
            seen.add(f)
            todo += LAYERS[f][2]
    return seen


def check_table():
    """Each row links only rows above it (so the table has no cycle), with a known kind."""
    problems, above = [], set()
    for f, (_, kind, deps) in LAYERS.items():
        if kind not in ("cpu", "device", "viewer"):
            problems.append(f"engine/layers.txt: {f}: kind {kind} is none of cpu, device, viewer")
        problems += [f"engine/layers.txt: {f} links {d}, which is not a row above it" for d in deps if d not in above]
        above.add(f)
    return problems


def layer_of(path):
    """(layer or None, why-not-layered) of a repository path. The public headers (include/candela/)
    are the api layer's."""
    parts = path.split("/")
    if parts[0] == "include" and len(parts) > 2 and parts[1] == "candela":
        return "api"
    if parts[0] == "shaders" and len(parts) > 2 and parts[1] == "shared":
        return "shared"
    if parts[0] == "engine" and len(parts) > 2:
        return parts[1]
    return None


def resolve(root, src, inc):
    cands = [os.path.join(os.path.dirname(src), inc), os.path.join("engine", inc), os.path.join("shaders", inc),
             os.path.join("include", inc)]
    if not src.startswith(("engine/", "shaders/")):
        cands += [os.path.join("app", inc), os.path.join("tests/unit", inc), os.path.join("tests/fuzz", inc)]
    for c in cands:
        c = os.path.normpath(c)
        if os.path.isfile(os.path.join(root, c)):
            return c
    return None


def consumer_rule(path):
    for prefix, folders in CONSUMERS:
        if path == prefix or (prefix.endswith("/") and path.startswith(prefix)):
            allowed = set(folders)
            for f in folders:
                allowed |= reach(f)
            return prefix, allowed
    return None, set(ALL)


def sources(root):
    for top in SCAN:
        for d, dirs, names in os.walk(os.path.join(root, top)):
            dirs[:] = sorted(x for x in dirs if x not in SKIP_DIRS)
            for n in sorted(names):
                if n.endswith(EXTS):
                    yield os.path.relpath(os.path.join(d, n), root)


def check_includes(root, direct):
    errors, notes, count = [], [], 0
    for src in sources(root):
        if src.startswith("shaders/shared/"):
            continue  # the shared headers include only each other
        own = layer_of(src)
        if src.startswith("engine/"):
            if src.count("/") == 1:
                if not src.endswith("CMakeLists.txt"):
                    errors.append(f"{src}: a file at engine/'s root belongs to no layer; put it in its job's folder")
                continue
            if own not in LAYERS:
                errors.append(f"{src}: folder engine/{own} is not in the layer table (engine/layers.txt)")
                continue
            rule, allowed = f"engine/{own}", reach(own) | {own}
        else:
            parts = src.split("/")
            if parts[:2] == ["tests", "unit"] and len(parts) > 3 and parts[2] not in LAYERS:
                errors.append(f"{src}: tests/unit/{parts[2]} is no folder of the layer table (engine/layers.txt); "
                              f"a unit test goes in the folder of what it tests")
                continue
            rule, allowed = consumer_rule(src)
        with open(os.path.join(root, src), encoding="utf-8", errors="replace") as f:
            lines = f.readlines()
        for number, line in enumerate(lines, 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            target = resolve(root, src, m.group(1))
            if target is None:
                errors.append(f"{src}:{number}: includes \"{m.group(1)}\", which resolves to no file")
                continue
            layer = layer_of(target)
            if layer is None:
                continue  # a test helper or an app-local header: not layered
            count += 1
            if layer not in LAYERS:
                errors.append(f"{src}:{number}: includes {target}, in engine/{layer}, which is not in the layer table")
                continue
            if layer in allowed:
                if direct and own in LAYERS and layer != own and layer not in LAYERS[own][2]:
                    notes.append(f"{src}:{number}: includes {m.group(1)} ({layer}): allowed through the table, "
                                 f"not a direct arrow of {own}")
                continue
            if own in LAYERS and own in reach(layer):
                kind = f"which is in a higher layer ({layer}, {LAYERS[layer][0]}, depends on {own})"
            elif own in LAYERS:
                others = ", ".join(sorted(allowed - {own}))
                kind = f"which is in an unrelated layer ({layer}, {LAYERS[layer][0]}: {own} may include " + \
                       (f"only {others})" if others else "no other layer)")
            else:
                kind = f"which is in layer {layer} ({LAYERS[layer][0]}), outside what {rule} may include " \
                       f"({', '.join(sorted(allowed)) or 'nothing'})"
            errors.append(f"{src}:{number}: includes {m.group(1)} {kind}")
    return errors, notes, count


NAMESPACE_OPEN = re.compile(r"^[ \t]*namespace[ \t]+(candela(?:::\w+)*)[ \t]*\{", re.M)
FORWARD_DECLARATION = re.compile(r"^(?:(?:class|struct)\s+\w+|enum\s+class\s+\w+\s*:\s*[\w:]+)\s*;$")


def within(opened, namespace):
    """Whether `opened` is `namespace` or nested in it."""
    return opened == namespace or opened.startswith(namespace + "::")


def owns(namespace, opened):
    """Whether a file of the row whose namespace is `namespace` may open `opened`: the row's own or
    one nested in it, but not one another row with a longer name owns (core's candela is not
    scene's candela::scene)."""
    return within(opened, namespace) and not any(len(other) > len(namespace) and within(opened, other)
                                                 for other in NAMESPACES.values())


def block_body(text, brace):
    """The text between the brace at `brace` and its match (None when unbalanced)."""
    depth = 0
    for i in range(brace, len(text)):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        if depth == 0:
            return text[brace + 1:i]
    return None


def check_namespaces(root):
    """Each file of engine/FOLDER declares its code in its row's namespace (engine/layers.txt), or
    one nested in it; a block of forward declarations only may name another row's namespace (a
    header naming a type it only points to). tests/unit/FOLDER may also use candela::test."""
    errors = []
    for src in sources(root):
        parts = src.split("/")
        if parts[0] == "engine" and len(parts) > 2 and parts[1] in LAYERS:
            folder, extra = parts[1], ()
        elif parts[:2] == ["tests", "unit"] and len(parts) > 3 and parts[2] in LAYERS:
            folder, extra = parts[2], ("candela::test",)
        else:
            continue
        text = open(os.path.join(root, src), encoding="utf-8", errors="replace").read()
        code = re.sub(r"//[^\n]*", "", text)
        for m in NAMESPACE_OPEN.finditer(code):
            opened = m.group(1)
            if owns(NAMESPACES[folder], opened) or any(within(opened, e) for e in extra):
                continue
            body = block_body(code, m.end() - 1) or ""
            statements = [s.strip() + ";" for s in body.split(";") if s.strip()]
            if statements and all(FORWARD_DECLARATION.match(" ".join(s.split())) for s in statements):
                continue
            line = code.count("\n", 0, m.start()) + 1
            errors.append(f"{src}:{line}: declares code in {opened}; engine/layers.txt gives {folder} the namespace "
                          f"{NAMESPACES[folder]}" + (f" (tests may also use {extra[0]})" if extra else ""))
    return errors


def check_cmake(root):
    """engine/FOLDER/CMakeLists.txt links each layer's target to what its row of the table names
    (candela_engine_library, engine/CMakeLists.txt); any candela_* library a folder links besides
    must be a direct link of its row (or no layer's, as candela_shaders)."""
    errors = []
    by_target = {t: f for f, (t, _, _) in LAYERS.items()}
    external = {"candela_warnings", "candela_shaders", "candela_fuzz_third_party", "candela_draco_decoder",
                "candela_draco_archive"}
    for folder, (target, _, deps) in LAYERS.items():
        if folder == "shared":
            continue
        path = os.path.join(root, "engine", folder, "CMakeLists.txt")
        if not os.path.isfile(path):
            errors.append(f"engine/{folder}/CMakeLists.txt: missing (the layer {folder} builds {target})")
            continue
        text = re.sub(r"#[^\n]*", "", open(path, encoding="utf-8").read())
        # The api layer is an object library (engine/api/CMakeLists.txt says why).
        if not re.search(r"candela_engine_library\(\s*" + target + r"\b", text) and not (
                folder == "api" and re.search(r"add_library\(\s*" + target + r"\s+OBJECT\b", text)):
            errors.append(f"engine/{folder}/CMakeLists.txt: does not build {target} with candela_engine_library")
        linked = set()
        for m in re.finditer(r"target_link_libraries\(\s*(\w+)(.*?)\)", text, re.S):
            if m.group(1) == target:
                linked |= set(re.findall(r"\bcandela_\w+", m.group(2)))
        for lib in sorted(linked - external):
            if lib not in by_target:
                errors.append(f"engine/{folder}/CMakeLists.txt: {target} links {lib}, which is no layer's target")
            elif by_target[lib] not in deps:
                errors.append(f"engine/{folder}/CMakeLists.txt: {target} links {lib} ({by_target[lib]}), "
                              f"which its row of engine/layers.txt does not link")
    return errors


DOC = "docs/architecture.md"
DOC_WRITER = "written from engine/layers.txt by tools/check_layers.py --write-docs"
TABLE_MARKS = (f"<!-- layer table: {DOC_WRITER}; the job column is the doc's -->", "<!-- end of layer table -->")
LEVELS_MARKS = (f"<!-- layer levels: {DOC_WRITER} -->", "<!-- end of layer levels -->")
TABLE_HEADER = ["| folder | CMake target | namespace | kind | links (direct) | job |", "|---|---|---|---|---|---|"]


def doc_levels():
    """The levels diagram: level 0 links nothing, level n links something of level n-1."""
    level = {}
    for f, (_, _, deps) in LAYERS.items():
        level[f] = 1 + max((level[d] for d in deps), default=-1)
    return ["```", *[f"{n}  " + "   ".join(f for f in LAYERS if level[f] == n) for n in range(max(level.values()) + 1)],
            "```"]


def doc_table(old):
    """The table's lines from the layer table, each row's job cell taken from `old` (the doc's lines
    between the marks); rows of folders that are no layer (app) are kept after the layers'."""
    columns = old[0].count("|") - 1 if old else 0
    jobs, others = {}, []
    for line in old[2:]:
        cells = line.strip()[1:-1].split(" | ", columns - 1)
        folder = cells[0].strip()
        if folder in LAYERS or folder == "shaders/shared":
            jobs[folder] = cells[-1].strip()
        else:
            others.append(line)
    rows = []
    for f, (target, kind, deps) in LAYERS.items():
        folder = "shaders/shared" if f == "shared" else f
        rows.append(f"| {folder} | {target} | {NAMESPACES[f]} | {kind} | {', '.join(deps) or '—'} | "
                    f"{jobs.get(folder, '')} |")
    return TABLE_HEADER + rows + others


def doc_sections(lines):
    """[(first line index, end mark index, the lines it should have)] of the two marked sections."""
    sections = []
    for (begin, end), write in ((TABLE_MARKS, doc_table), (LEVELS_MARKS, lambda old: doc_levels())):
        if begin not in lines or end not in lines:
            raise ValueError(f"{DOC}: the marks of a generated section are missing: {begin} … {end}")
        first, last = lines.index(begin) + 1, lines.index(end)
        sections.append((first, last, write(lines[first:last])))
    return sections


def check_doc(root):
    lines = open(os.path.join(root, DOC), encoding="utf-8").read().split("\n")
    try:
        sections = doc_sections(lines)
    except ValueError as e:
        return [str(e)]
    errors = []
    for first, last, want in sections:
        have = lines[first:last]
        for i in range(max(len(have), len(want))):
            h, w = (have[i] if i < len(have) else "(none)"), (want[i] if i < len(want) else "(none)")
            if h != w:
                errors.append(f"{DOC}:{first + i + 1}: differs from engine/layers.txt: has '{h}', should have '{w}' "
                              f"(tools/check_layers.py --write-docs rewrites it)")
                break
    return errors


def write_doc(root):
    path = os.path.join(root, DOC)
    lines = open(path, encoding="utf-8").read().split("\n")
    for first, last, want in reversed(doc_sections(lines)):
        lines[first:last] = want
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    root = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    load(root)
    problems = check_table()
    if problems:
        print("\n".join(problems))
        return 1
    if "--write-docs" in argv:
        write_doc(root)
        return 0
    errors, notes, count = check_includes(root, "--direct" in argv)
    errors += check_namespaces(root)
    errors += check_doc(root)
    if "--no-cmake" not in argv:
        errors += check_cmake(root)
    for line in notes:
        print("note: " + line)
    for line in errors:
        print(line)
    print(f"check_layers: {count} layered includes checked, {len(errors)} problems", file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
