#!/usr/bin/python3
"""Every equation and section the code cites resolves inside the checkout: each "theory En"
(or the older "SPEC En") and "theory §n" ("SPEC §n") in src/, tests/, bench/, examples/ and
docs/ names a heading of docs/theory.md ("### (En) ..." or "## §n ...").

  check_citations.py ROOT"""
import os
import re
import sys

root = sys.argv[1]
theory = open(os.path.join(root, "docs", "theory.md"), encoding="utf-8").read()
equations = set(re.findall(r"^#+ \((E\d+)\)", theory, re.M))
sections = set(re.findall(r"^#+ §(\d+)", theory, re.M))
cite_eq = re.compile(r"(?:SPEC|theory|theory\.md)\s+(E\d+)(?:\s*[-–…]+\s*E?(\d+))?")
cite_sec = re.compile(r"(?:SPEC|theory|theory\.md)\s+§(\d+)")
missing = []
count = 0
for top in ("src", "tests", "bench", "examples", "docs", "fuzz", "scripts"):
    for d, _, files in os.walk(os.path.join(root, top)):
        for f in files:
            if not f.endswith((".cpp", ".hpp", ".h", ".py", ".toml", ".md", ".sh", ".txt")):
                continue
            path = os.path.join(d, f)
            text = open(path, encoding="utf-8", errors="replace").read()
            for m in cite_eq.finditer(text):
                first = int(m.group(1)[1:])
                last = int(m.group(2)) if m.group(2) else first
                for k in range(first, max(first, last) + 1):
                    count += 1
                    if f"E{k}" not in equations:
                        missing.append(f"{os.path.relpath(path, root)}: E{k}")
            for m in cite_sec.finditer(text):
                count += 1
                if m.group(1) not in sections:
                    missing.append(f"{os.path.relpath(path, root)}: §{m.group(1)}")
print(f"{count} citations, {len(equations)} equations and {len(sections)} sections in docs/theory.md, "
      f"{len(missing)} unresolved")
for m in sorted(set(missing)):
    print("  unresolved:", m)
sys.exit(1 if missing or count == 0 else 0)
