#!/usr/bin/env python3
"""The allowed include graph between Mozzi's layers and core/ domains (issue 24).

DESIGN.md's layers point down only: app/ over views/ over devices/ over core/,
and inside core/ each domain includes only the domains below it in ALLOWED.
This check reads every #include of a file under core/, devices/, views/ and
app/ and fails, naming file, line and the two units, on an include the table
does not allow. Run by ctest (test layers_include_graph):

    tests/layers_check.py SOURCE_DIR [STAMP]

(with STAMP, the file is touched when the check passes: core/CMakeLists.txt
runs it so, before any core/ library is built, and a forbidden include fails
the build). The same table is core/'s CMake link graph:

    tests/layers_check.py --core-links

prints one line per core/ domain, "domain,dependency,...", and
core/CMakeLists.txt links each domain's library to the libraries of the
domains it may include, and to no others.

To allow a new dependency, add it to ALLOWED here: the table is the rule.
"""

import os
import re
import sys

CORE = ["common", "signal", "io", "modal", "stiffness", "tire", "stability", "geometry", "gap", "report"]

# unit -> the units it may include (besides itself). A core/ domain is
# "core/<domain>"; devices/, views/ and app/ are one unit each.
ALLOWED = {
    "core/common": set(),
    # Time records and windows (signal) build on the common types.
    "core/signal": {"core/common"},
    # File exchange and the project store keep time records (signal).
    "core/io": {"core/common", "core/signal"},
    "core/modal": {"core/common", "core/signal", "core/io"},
    "core/stiffness": {"core/common", "core/signal", "core/io"},
    "core/tire": {"core/common", "core/signal", "core/io"},
    "core/stability": {"core/common", "core/signal", "core/io"},
    "core/geometry": {"core/common", "core/signal", "core/io", "core/modal"},
    "core/gap": {"core/common", "core/signal", "core/io", "core/modal", "core/stiffness", "core/tire",
                 "core/stability"},
    "core/report": {"core/" + d for d in CORE if d != "report"},
    "devices": {"core/" + d for d in CORE},
    "views": {"core/" + d for d in CORE} | {"devices"},
    "app": {"core/" + d for d in CORE} | {"devices", "views"},
}

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]((core|devices|views|app)/[^">]+)[">]')


def unit(path):
    """The unit a path under the source tree belongs to, or None."""
    parts = path.split("/")
    if parts[0] == "core":
        return "core/" + parts[1] if len(parts) > 2 else "core"
    if parts[0] in ("devices", "views", "app"):
        return parts[0]
    return None


def main(root):
    problems = []
    seen = set()
    files = 0
    for top in ("core", "devices", "views", "app"):
        for folder, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                if not name.endswith((".h", ".cpp")):
                    continue
                path = os.path.relpath(os.path.join(folder, name), root)
                source = unit(path)
                files += 1
                if source not in ALLOWED:
                    problems.append(f"{path}: not in a unit of the table (core/<domain>, devices, views, app)")
                    continue
                with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = unit(m.group(1))
                        if target == source:
                            continue
                        seen.add((source, target))
                        if target not in ALLOWED[source]:
                            problems.append(f"{path}:{number}: {source} includes {target} ({m.group(1)}); "
                                            f"allowed for {source}: {', '.join(sorted(ALLOWED[source])) or 'nothing'}")
    for p in problems:
        print("layers: " + p, file=sys.stderr)
    if problems:
        print(f"layers: {len(problems)} include(s) against the table in tests/layers_check.py", file=sys.stderr)
        return 1
    print(f"layers: {files} files, {len(seen)} unit-to-unit dependencies, all allowed by the table")
    return 0


def core_links():
    """core/ domains with the domains each may include, for CMake."""
    for d in CORE:
        deps = [x for x in CORE if "core/" + x in ALLOWED["core/" + d]]
        print(",".join([d] + deps))
    return 0


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--core-links":
        sys.exit(core_links())
    status = main(sys.argv[1] if len(sys.argv) > 1 else ".")
    if status == 0 and len(sys.argv) > 2:
        with open(sys.argv[2], "w", encoding="utf-8") as stamp:
            stamp.write("layers: ok\n")
    sys.exit(status)
