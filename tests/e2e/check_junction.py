#!/usr/bin/env python3
"""A growing crack that reaches another line drawn in its body, where following it is not
supported, stops the run with a diagnosis.

Usage: check_junction.py RUPTURE INPUT OUT   (LAUNCH="mpiexec -n 2": run it under that launcher;
every rank takes the same decision and stops alike)
tests/inputs/crack_junction.toml: the inclined centre crack's right tip kinks towards a second
crack ("wall") drawn in the same plate, tied on at both ends. The wall is on the edge of the
crack's reach (the part below it is one no growing line changes), but the tip runs along it and
past its end, for its tied extension: intact material the crack would have to run on through,
into the part beyond its reach (docs/fracture.md "Junctions"), so the run must
  - exit with the unstable run's code (2), naming both interfaces, the tied extension, the place
    and the time;
  - keep what it wrote: run.json with status "failed", the history, the crack's path;
  - have grown the crack first (the kink is the criterion's, about -41 degrees), every laid
    segment at least one cell from the wall's line and its tied extensions, and stopped before
    the end time.
"""
import csv
import json
import math
import os
import subprocess
import sys

rupture, inp, out = sys.argv[1:4]
launch = os.environ.get("LAUNCH", "").split()
p = subprocess.run(launch + [rupture, "run", inp, "-o", out, "--overwrite", "--quiet"], capture_output=True, text=True)
ok = True


def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and cond


err = p.stderr
check(p.returncode == 2, f"exit code {p.returncode} (2: the run went unstable / stopped with a diagnosis)")
for s in ["interface 'crack' has its tip at", "interface 'wall''s tied extension", "Junctions", "at t = "]:
    check(s in err, f"the message names {s!r}")
r = json.load(open(f"{out}/run.json"))
check(r["status"] == "failed", f"run.json status {r['status']}")
h = r["input"]["grid"]["cell_size"]
hist = list(csv.DictReader(open(f"{out}/history.csv")))
t_stop = float(hist[-1]["time"])
check(len(hist) > 10 and t_stop < 200e-6, f"history kept, {len(hist)} rows to {t_stop*1e6:.1f} us (end 200 us)")

rows = list(csv.DictReader(open(f"{out}/crack_path_crack.csv")))
right = [r for r in rows if r["tip"] == "1"]
check(len(right) >= 10, f"the right tip grew {len(right)} segments first")
check(-46 < float(right[0]["angle"]) < -36, f"its first segment at {float(right[0]['angle']):.2f} degrees")

# The wall: its line and its tied extensions (the line's straight extension to the plate's edges).
ax, ay, bx, by = 0.015, -0.0028868, 0.025, 0.0028868


def dist_to_segment(px, py, x0, y0, x1, y1):
    vx, vy = x1 - x0, y1 - y0
    u = max(0.0, min(1.0, ((px - x0) * vx + (py - y0) * vy) / (vx * vx + vy * vy)))
    return math.hypot(px - x0 - u * vx, py - y0 - u * vy)


def seg_dist(p0, p1, q0, q1):
    # Segments that cross are at distance 0.
    def side(o, d, x):
        return (d[0] - o[0]) * (x[1] - o[1]) - (d[1] - o[1]) * (x[0] - o[0])
    if side(q0, q1, p0) * side(q0, q1, p1) < 0 and side(p0, p1, q0) * side(p0, p1, q1) < 0:
        return 0.0
    return min(dist_to_segment(*p0, *q0, *q1), dist_to_segment(*p1, *q0, *q1),
               dist_to_segment(*q0, *p0, *p1), dist_to_segment(*q1, *p0, *p1))


L = 1.0  # far beyond the plate: the extensions as long straight lines
ux, uy = (bx - ax) / math.hypot(bx - ax, by - ay), (by - ay) / math.hypot(bx - ax, by - ay)
wall = [((ax - L * ux, ay - L * uy), (bx + L * ux, by + L * uy))]
prev = (0.008660254037844387, 0.0051)
closest = math.inf
for row in right:
    cur = (float(row["x"]), float(row["y"]))
    closest = min(closest, min(seg_dist(prev, cur, *w) for w in wall))
    prev = cur
check(closest >= h * (1 - 1e-9), f"every laid segment {closest*1e3:.3f} mm (>= one cell, {h*1e3:.1f} mm) from the wall and its extension")
check(dist_to_segment(*prev, ax, ay, bx, by) < 3 * h, f"the tip stopped {dist_to_segment(*prev, ax, ay, bx, by)*1e3:.2f} mm from the wall")
sys.exit(0 if ok else 1)
