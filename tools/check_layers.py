#!/usr/bin/env python3
"""Candela's layer check: every #include "..." points down the layer table below.

    tools/check_layers.py [ROOT] [--direct] [--no-cmake]

Reads every quoted #include in engine/, app/, tools/, tests/ and shaders/ (*.h, *.cpp, *.in),
resolves it as the build does (the including file's folder, engine/, shaders/; for app/, tools/ and
tests/ also app/, tests/unit, tests/fuzz), and maps both ends to a layer: a folder of engine/ (its
CMake target in LAYERS), or "shared" for shaders/shared/*.h. Includes that resolve outside engine/
and shaders/shared (test helpers, app-local headers) are not layered.

A file in engine/FOLDER may include its own folder and every folder reachable from it along the
arrows of LAYERS (what its target links, directly or further down). Anything else fails, one line per
include: "points up" when the included folder depends on the including one, "sideways" when neither
reaches the other. A file outside engine/ is held to the CONSUMERS row its path matches first (the
binary it is compiled into). Exit status 1 on any violation, 0 otherwise.

--direct   also reports includes of a folder that is reachable but not a direct arrow (informational:
           keeps the table's direct lists honest; never fails the run).
--no-cmake skips the second check: every candela_* library named in engine/*/CMakeLists.txt
           target_link_libraries of a layer's target must be a layer the table allows it, and every
           direct arrow of the table must be linked.

Register with ctest (tests/CMakeLists.txt):
    find_package(Python3 REQUIRED COMPONENTS Interpreter)
    add_test(NAME layers COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/tools/check_layers.py ${PROJECT_SOURCE_DIR})
    set_tests_properties(layers PROPERTIES LABELS unit)
"""
import os
import re
import sys

# ---- The layer table (the same as engine/CMakeLists.txt's header and docs) ---------------------
# folder: (CMake target, direct dependencies: folders it may include and its target links)
LAYERS = {
    "core":      ("candela_core",      []),
    "shared":    ("candela_shared",    []),   # shaders/shared/*.h: GLSL and C++, header-only
    "animation": ("candela_animation", ["core"]),
    "scene":     ("candela_scene",     ["animation", "shared", "core"]),
    "geometry":  ("candela_geometry",  ["scene"]),
    "pose":      ("candela_pose",      ["scene", "core"]),
    "textures":  ("candela_textures",  ["core"]),
    "assets":    ("candela_assets",    ["scene", "geometry", "pose", "textures", "shared", "core"]),
    "ibl":       ("candela_ibl",       ["core"]),
    "reports":   ("candela_reports",   ["assets", "ibl", "shared", "core"]),
    "shader":    ("candela_shader",    []),
    "graph":     ("candela_graph",     []),
    "vk":        ("candela_vk",        ["shader", "core"]),
    "executor":  ("candela_executor",  ["graph", "vk"]),
    "gpu_scene": ("candela_gpu_scene", ["scene", "geometry", "shared", "vk"]),
    "passes":    ("candela_passes",    ["executor", "gpu_scene", "graph", "pose", "scene", "geometry",
                                        "shader", "shared", "vk"]),
    "ibl_maps":  ("candela_ibl_maps",  ["passes", "executor", "graph", "vk", "assets", "ibl", "reports", "core"]),
    "render":    ("candela_render",    ["ibl_maps", "passes", "gpu_scene", "executor", "graph", "vk", "shader",
                                        "assets", "pose", "scene", "ibl", "shared", "core"]),
    "soak":      ("candela_soak",      ["render", "assets", "vk", "core"]),
    "ui":        ("candela_ui",        ["render", "executor", "graph", "vk", "shader", "assets", "pose", "scene",
                                        "ibl", "core"]),
}
ALL = sorted(LAYERS)
CPU = ["core", "shared", "animation", "scene", "geometry", "pose", "textures", "assets", "ibl", "reports", "shader", "graph"]
ENGINE_UNIT_TESTS = ["device_select_test.cpp", "device_profile_test.cpp", "memory_type_test.cpp", "msaa_choice_test.cpp", "graph_pass_context_test.cpp",
                     "graph_msaa_test.cpp", "draw_list_test.cpp", "visibility_frame_test.cpp", "ibl_sample_tables_test.cpp",
                     "orbit_controls_test.cpp", "ibl_report_table_test.cpp", "forward_shader_test.cpp",
                     "forward_tables_test.cpp", "skin_morph_dispatch_test.cpp", "index_values_test.cpp",
                     "swapchain_choices_test.cpp", "pipeline_cache_file_test.cpp", "bright_texels_test.cpp", "panel_layout_test.cpp"]

CLI_ENUM_HEADERS = ["passes/debug_view.h", "passes/draw_selection.h", "passes/tonemap_operator.h", "passes/shading_model.h",
                    "passes/precompile.h", "passes/shading_path.h", "ui/viewer_panels.h", "vk/device_profile.h"]

# ---- Files outside engine/: the first row whose path matches (a file, or a folder ending in /) --
# (path, folders it may include (and everything below them), single headers it may include besides)
CONSUMERS = [
    # candela_cli: the argument parser, tested without the engine (tests/cli). The names of the debug
    # views, draw selections, tonemap operators, shading models, precompile choices and viewer panels are header-only enums with their
    # names tables; candela_passes and candela_ui are not linked.
    *[(f"app/{name}", ["ibl", "core", "shared"], CLI_ENUM_HEADERS)
      for name in ["cli.h", "cli.cpp", "cli_commands.cpp", "cli_flags.h", "cli_flags.cpp", "cli_help.cpp", "cli_values.h", "cli_values.cpp",
                   "flag_spec.h", "flag_groups.h", "flag_groups.cpp", "common_options.h", "scene_render_options.h",
                   *[f"{command}_cli.{ext}" for command in ["render", "view", "bench", "ibl_report", "scale_report",
                                                            "quality_report", "soak", "diff", "info"] for ext in ["h", "cpp"]]]],
    ("app/", ALL, []),
    ("tools/bench/graph_compile_bench.cpp", ["graph"], []),
    ("tools/bench/pose_bench.cpp", ["assets", "pose"], []),
    ("tools/bench/exr_read_bench.cpp", ["assets"], []),
    ("tools/", ALL, []),
    # candela_engine_unit_tests: no device, no window, but the device-side and viewer libraries.
    *[(f"tests/unit/{name}", ["vk", "executor", "gpu_scene", "passes", "ibl_maps", "ui"], []) for name in ENGINE_UNIT_TESTS],
    # candela_unit_tests and the helpers every test binary shares: the CPU libraries only.
    ("tests/unit/", CPU, []),
    # The fuzz build configures nothing above the readers (and the images `candela diff` reads).
    ("tests/fuzz/", ["assets", "pose", "reports"], []),
    ("tests/", ALL, []),
    # candela_shaders defines shader/builtin_shaders.h.
    ("shaders/", ["shader", "shared"], []),
]

SCAN = ("engine", "app", "tools", "tests", "shaders")
SKIP_DIRS = {"build", "regressions", "uri-folder", "golden", ".git"}
EXTS = (".h", ".cpp", ".in")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def reach(folder):
    """Folders reachable from `folder` along the table's arrows (without itself)."""
    seen, todo = set(), list(LAYERS[folder][1])
    while todo:
        f = todo.pop()
        if f not in seen:
            seen.add(f)
            todo += LAYERS[f][1]
    return seen


def check_table():
    problems = []
    for f, (_, deps) in LAYERS.items():
        problems += [f"layer table: {f} depends on unknown layer {d}" for d in deps if d not in LAYERS]
    if problems:
        return problems
    return [f"layer table: {f} reaches itself (a cycle)" for f in LAYERS if f in reach(f)]


def layer_of(path):
    """(layer or None, why-not-layered) of a repository path."""
    parts = path.split("/")
    if parts[0] == "shaders" and len(parts) > 2 and parts[1] == "shared":
        return "shared"
    if parts[0] == "engine" and len(parts) > 2:
        return parts[1]
    return None


def resolve(root, src, inc):
    cands = [os.path.join(os.path.dirname(src), inc), os.path.join("engine", inc), os.path.join("shaders", inc)]
    if not src.startswith(("engine/", "shaders/")):
        cands += [os.path.join("app", inc), os.path.join("tests/unit", inc), os.path.join("tests/fuzz", inc)]
    for c in cands:
        c = os.path.normpath(c)
        if os.path.isfile(os.path.join(root, c)):
            return c
    return None


def consumer_rule(path):
    for prefix, folders, headers in CONSUMERS:
        if path == prefix or (prefix.endswith("/") and path.startswith(prefix)):
            allowed = set(folders)
            for f in folders:
                allowed |= reach(f)
            return prefix, allowed, set(headers)
    return None, set(ALL), set()


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
                errors.append(f"{src}: folder engine/{own} is not in the layer table (tools/check_layers.py LAYERS)")
                continue
            rule, allowed, headers = f"engine/{own}", reach(own) | {own}, set()
        else:
            rule, allowed, headers = consumer_rule(src)
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
            if layer in allowed or os.path.relpath(target, "engine") in headers:
                if direct and own in LAYERS and layer != own and layer not in LAYERS[own][1]:
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


def check_cmake(root):
    """engine/FOLDER/CMakeLists.txt: the candela_* libraries each layer's target links."""
    errors = []
    by_target = {t: f for f, (t, _) in LAYERS.items()}
    external = {"candela_warnings", "candela_shaders", "candela_fuzz_third_party", "candela_draco_decoder",
                "candela_draco_archive"}
    for folder, (target, deps) in LAYERS.items():
        if folder == "shared":
            continue
        path = os.path.join(root, "engine", folder, "CMakeLists.txt")
        if not os.path.isfile(path):
            errors.append(f"engine/{folder}/CMakeLists.txt: missing (the layer {folder} builds {target})")
            continue
        text = re.sub(r"#[^\n]*", "", open(path, encoding="utf-8").read())
        linked = set()
        for m in re.finditer(r"target_link_libraries\(\s*(\w+)(.*?)\)", text, re.S):
            if m.group(1) != target:
                continue
            linked |= set(re.findall(r"\bcandela_\w+", m.group(2)))
        allowed = reach(folder)
        for lib in sorted(linked - external):
            if lib not in by_target:
                errors.append(f"engine/{folder}/CMakeLists.txt: {target} links {lib}, which is no layer's target")
            elif by_target[lib] not in allowed:
                errors.append(f"engine/{folder}/CMakeLists.txt: {target} links {lib} ({by_target[lib]}), "
                              f"which is not below {folder} in the layer table")
        for dep in deps:
            if LAYERS[dep][0] not in linked:
                errors.append(f"engine/{folder}/CMakeLists.txt: {target} does not link {LAYERS[dep][0]}, "
                              f"a direct dependency of {folder} in the layer table")
    return errors


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    root = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    problems = check_table()
    if problems:
        print("\n".join(problems))
        return 1
    errors, notes, count = check_includes(root, "--direct" in argv)
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
