#!/usr/bin/env python3
"""Checks the library's layers: no file of a module includes a module above it.

Usage: check_layers.py SOURCE_DIR

The rules are LAYERS below (docs/architecture.md, "Modules, lowest first", says why):
each module lists the modules it may include, which must lie below it, so the
modules form no loop. Every file under src/<module>/ and include/stockbridge/<module>/
is read; an #include of "stockbridge/<other>/..." or "../<other>/..." that its
module's rule does not allow is printed as FILE:LINE: <module> includes <other>
(allowed: ...). Exits 1 if there is any, 0 otherwise.
"""
import os
import re
import sys

# module: the modules it may include (each below it). Lowest first.
LAYERS = {
    "core": [],
    "numerics": ["core"],
    "section": ["core"],
    "strand": ["core"],
    "cable": ["core", "numerics", "section"],
    "damper": ["core", "numerics", "section", "cable"],
    "identification": ["core", "numerics", "section", "cable", "damper"],
    "span": ["core", "numerics", "strand", "damper"],
    "design": ["core", "numerics", "damper", "span"],
    "line": ["core", "span"],
    "io": ["core", "strand", "section", "cable", "damper", "identification", "span", "design", "line"],
    "measurements": ["core", "numerics", "span", "io"],
    "requests": ["core", "numerics", "section", "strand", "cable", "damper", "identification", "span", "design",
                 "line", "io", "measurements"],
    "report": ["core", "numerics", "damper", "span", "design", "line", "io", "measurements", "requests"],
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"(?:stockbridge/|\.\./)([a-z_]+)/')


def check_rules():
    """The rules themselves: each module's allowed modules come before it (no loop)."""
    order = list(LAYERS)
    for module, allowed in LAYERS.items():
        for other in allowed:
            if other not in LAYERS or order.index(other) >= order.index(module):
                return [f"LAYERS: {module} may include {other}, which is not below it"]
    return []


def violations(source):
    found = []
    for root in (os.path.join(source, "src"), os.path.join(source, "include", "stockbridge")):
        for module in sorted(LAYERS):
            folder = os.path.join(root, module)
            for directory, _, files in os.walk(folder):
                for name in sorted(files):
                    if not name.endswith((".cpp", ".hpp", ".h", ".in")):
                        continue
                    path = os.path.join(directory, name)
                    with open(path, encoding="utf-8", errors="replace") as f:
                        for number, line in enumerate(f, 1):
                            match = INCLUDE.match(line)
                            if not match:
                                continue
                            other = match.group(1)
                            if other == module or other not in LAYERS or other in LAYERS[module]:
                                continue
                            where = os.path.relpath(path, source)
                            found.append(f"{where}:{number}: {module} includes {other} (allowed: "
                                         f"{', '.join(LAYERS[module]) or 'nothing'})")
    return found


def main():
    source = sys.argv[1] if len(sys.argv) > 1 else "."
    found = check_rules() + violations(source)
    for line in found:
        print(line)
    print(f"layers: {len(found)} include(s) against the rules")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
