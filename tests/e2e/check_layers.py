#!/usr/bin/env python3
"""The layer table of docs/architecture.md against the sources' includes.

For every folder of src/ the table's "includes from" column must be exactly the set of other
src/ folders that `#include "folder/..."` lines in that folder name, every folder must have a
row, and a folder may include only from folders above it in the table, but for the exceptions
the page names (a line "- **lower → upper**: ..." under "One include goes from a lower layer").
Usage: check_layers.py SOURCE_DIR. Exit 1 with the differences.
"""
import pathlib
import re
import sys


def table(doc):
    """Rows (folder, set of folders it includes from) in the table's order."""
    rows = []
    for line in doc.splitlines():
        m = re.match(r"^\| `([a-z_]+)` \|.*\| ([^|]*) \|$", line)
        if not m:
            continue
        deps = {d.strip().strip("*") for d in m.group(2).split(",")} - {"—", ""}
        rows.append((m.group(1), deps))
    return rows


def upward_exceptions(doc):
    return set(re.findall(r"^- \*\*([a-z_]+) → ([a-z_]+)\*\*", doc, flags=re.M))


def includes(src, folder):
    found = set()
    for f in (src / folder).rglob("*"):
        if f.suffix not in (".hpp", ".cpp"):
            continue
        for m in re.finditer(r'^#include "([a-z_]+)/', f.read_text(), flags=re.M):
            if m.group(1) != folder:
                found.add(m.group(1))
    return found


def main():
    root = pathlib.Path(sys.argv[1])
    doc = (root / "docs" / "architecture.md").read_text()
    src = root / "src"
    rows = table(doc)
    folders = sorted(p.name for p in src.iterdir() if p.is_dir())
    errors = []
    listed = [r[0] for r in rows]
    for f in folders:
        if f not in listed:
            errors.append(f"src/{f}: no row in docs/architecture.md's layer table")
    exceptions = upward_exceptions(doc)
    for position, (folder, documented) in enumerate(rows):
        if not (src / folder).is_dir():
            errors.append(f"table row `{folder}`: no folder src/{folder}")
            continue
        actual = includes(src, folder)
        if actual != documented:
            errors.append(f"src/{folder} includes from {sorted(actual)}; the table says {sorted(documented)}")
        above = set(listed[:position])
        for dep in sorted(actual - above):
            if (folder, dep) not in exceptions:
                errors.append(f"src/{folder} includes from {dep}, which is not above it in the table "
                              f"and not a named exception")
    for e in errors:
        print(e)
    print(f"layers: {len(rows)} folders in the table, {len(folders)} in src/, {len(errors)} differences")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
