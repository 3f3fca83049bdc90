#!/usr/bin/env python3
"""Finds names that clash between the sources of one target under the unity build, whichever batch
they land in: for each target of a unity build tree (CANDELA_UNITY_BUILD=ON), all of its batches
are compiled syntax-only as one translation unit, with the target's own flags.

A unity build compiles each batch of 8 sources as one unit, so two files of a target may not
declare the same name at namespace scope (anonymous namespaces included). The build finds a clash
only between files of the same batch; adding a file moves the batch boundaries, so a clash can
surface in someone else's change. This check finds them all at once (a few minutes; opt-in).

  tools/unity-name-check.py build/release [TARGET_SUBSTRING...]

Prints each target with its number of errors and the errors; exits 1 when any target has one.
"""
import collections
import json
import os
import re
import subprocess
import sys
import tempfile


def main() -> int:
    if len(sys.argv) < 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    build, wanted = sys.argv[1], sys.argv[2:]
    commands = json.load(open(os.path.join(build, "compile_commands.json")))
    targets = collections.defaultdict(list)
    for entry in commands:
        m = re.search(r"(.*/CMakeFiles/[^/]+\.dir)/Unity/unity_\d+_cxx\.cxx$", entry["file"])
        if m:
            targets[m.group(1)].append(entry)
    if not targets:
        print(f"{build}: no unity batches (configure with -DCANDELA_UNITY_BUILD=ON)", file=sys.stderr)
        return 2
    failed = False
    with tempfile.TemporaryDirectory() as scratch:
        for target, entries in sorted(targets.items()):
            name = os.path.basename(target).removesuffix(".dir")
            if wanted and not any(w in name for w in wanted):
                continue
            whole = os.path.join(scratch, name + ".cxx")
            with open(whole, "w") as out:
                for entry in entries:
                    out.write(open(entry["file"]).read())
            command = re.sub(r" -o \S+", " ", entries[0]["command"])
            command = re.sub(r" -c \S+", " -fsyntax-only -c " + whole, command)
            result = subprocess.run(command, shell=True, cwd=entries[0]["directory"], capture_output=True, text=True)
            errors = sorted({line for line in result.stderr.splitlines() if "error:" in line})
            print(f"{name}: {len(errors)} error(s)")
            for line in errors:
                print("  " + line)
            failed |= bool(errors) or result.returncode != 0
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
