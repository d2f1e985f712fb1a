#!/usr/bin/python3
"""Ties that follow the material (solver/tie_follow.hpp; docs/fracture.md, "A tie that follows the
material"), through the driver. tests/inputs/nucleation_site.toml at ratio 0.5 (the 4 mm site at
30 degrees stays intact: the plate split along it and tied over it and on to the edges), the
whole plate moving at 200 m/s across the grid, 3 mm (3 cells) in 15 us. Checks:
  1. the stations 0.75 mm either side of the line's middle move as in the plate without the line,
     to round-off (1e-9 of their largest elastic displacement, the move less the plate's rigid
     one): the tie was laid again where the material went (tests/test_tie_follow.cpp measures the
     same particle for particle; laid where drawn, they differ by 4 % of the elastic motion);
  2. the site stays intact (ratio 0.5);
  3. the same on nested levels (a fine box of 1 mm cells round the site in 2 mm ones, one step
     for all): the stations equal the undivided nested plate's within 1e-6 of their elastic
     displacement (tests/test_tie_follow.cpp bounds the residual at the box's edge). Its run
     directory (WORK_DIR/nested) is the reference of ctest restart_tie_follow_nested_stop.
Set LAUNCH (e.g. "mpiexec -n 2") to run under it.
Usage: check_tie_follow.py RUPTURE CASE WORK_DIR"""
import csv
import json
import os
import re
import shlex
import subprocess
import sys

rupture, case, work = sys.argv[1:4]
launch = shlex.split(os.environ.get("LAUNCH", ""))
os.makedirs(work, exist_ok=True)
V = 200.0
moving = ["parameters.ratio=0.5", f"bodies.plate.velocity=[0.0, {V}]", "grid.max=[0.04, 0.045]"]
failures = []


def run(name, *sets, path=case):
    out = os.path.join(work, name)
    args = launch + [rupture, "run", path, "-o", out, "--overwrite", "--quiet"]
    for s in sets:
        args += ["--set", s]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"FAIL: {name}: rupture exited {done.returncode}:\n{done.stderr}")
    return out, json.load(open(os.path.join(out, "run.json")))


def elastic(out, name, v):
    with open(os.path.join(out, "stations", f"{name}.csv")) as f:
        return [(float(r["time"]), float(r["ux"]), float(r["uy"]) - v * float(r["time"])) for r in csv.DictReader(f)]


split, rs = run("split", *moving)
text = open(case).read()
plain_path = os.path.join(work, "no_line.toml")
open(plain_path, "w").write(re.sub(r"\[interface\.site\].*?(?=\n\[)", "", text, flags=re.S))
whole, _ = run("no_line", *moving, path=plain_path)
if rs.get("cracks.site.nucleation_time") is not None:
    failures.append("the site came loose (ratio 0.5 must stay intact)")

worst, largest = 0.0, 0.0
for name in ("above", "below"):
    a, b = elastic(split, name, V), elastic(whole, name, V)
    if len(a) != len(b) or len(a) < 10:
        sys.exit(f"FAIL: station {name}: {len(a)} and {len(b)} samples")
    for ra, rb in zip(a, b):
        for k in (1, 2):
            worst = max(worst, abs(ra[k] - rb[k]))
            largest = max(largest, abs(rb[k]))
print(f"moving {V} m/s for {a[-1][0] * 1e6:.1f} us: stations against the plate without the line {worst:.3g} m "
      f"of {largest:.3g} m elastic")
if not worst <= 1e-9 * largest:
    failures.append(f"the split plate differs from the undivided one by {worst:.3g} m (bound round-off, 1e-9 of {largest:.3g})")

nested = ["grid.max=[0.04, 0.048]", "grid.coarse_cell_size=2e-3", "grid.refine.box.min=[0.008, 0.008]",
          "grid.refine.box.max=[0.032, 0.036]", "grid.refine.box.level=1", 'time.subcycling="none"']
split_n, _ = run("nested", *moving, *nested)
whole_n, _ = run("nested_no_line", *moving, *nested, path=plain_path)
worst_n, largest_n = 0.0, 0.0
for name in ("above", "below"):
    for ra, rb in zip(elastic(split_n, name, V), elastic(whole_n, name, V)):
        for k in (1, 2):
            worst_n = max(worst_n, abs(ra[k] - rb[k]))
            largest_n = max(largest_n, abs(rb[k]))
print(f"nested levels: stations against the plate without the line {worst_n:.3g} m of {largest_n:.3g} m elastic")
if not worst_n <= 1e-6 * largest_n:
    failures.append(f"nested: the split plate differs from the undivided one by {worst_n:.3g} m (bound 1e-6 of {largest_n:.3g})")

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("the tie follows the material: the moving split plate is the undivided plate")
