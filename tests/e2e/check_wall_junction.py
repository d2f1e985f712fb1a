#!/usr/bin/python3
"""A growing crack that reaches a line drawn in its own body on the edge of its reach
(docs/fracture.md "Junctions"; input/crack_reach.hpp): that line is followed as an interface
between two bodies is.

1. tests/inputs/wall_junction.toml is bond_junction.toml with the two plates drawn as one plate
   split by the bonded line (body = "plate"): the part above it is beyond the cut's reach. The
   two are one problem, so the stations of the two runs must agree to round-off (measured: equal
   to the bit), the bond's face below must change field at x = 10 mm (run.json lower_faces), and
   the cut must end on it at (10, 6) mm.
2. tests/inputs/crack_into_wall.toml: an inclined centre crack kinks into an edge crack ("wall")
   drawn in the same plate. The run must end normally (before the edge-of-reach junction it
   stopped there with a diagnosis); the right tip's last vertex lies on the wall's line; the
   wall's face above changes field exactly there (run.json upper_faces: the part between the
   crack's tie and the wall before that point, the part above the crack beyond it); the left tip
   runs out through the left edge, so the plate is in two pieces; the energy balance closes to
   1 % (measured 0.07 %).
4. tests/inputs/crack_into_tied_wall.toml: the same with the wall ending at x = 30 mm, tied on to
   the right edge. The crack ends on the wall; the piece it cuts off joins the part above the
   crack, and the wall's right tie holds it to the part below the wall (a pair of fields of its
   own): the opening across the tie (stations 0.75 mm either side, along the wall's normal) stays
   below 10 um (measured 3.3 um at most), while the wall's crack opens by more than 100 um
   (measured 242 um at 200 us). With the tie left on the wall's pair (a build without the
   stretch's own pair) the tie opened by 886 um: the piece came free along it.
3. The same problem turned by 90 degrees (every point (x, y) to (-y, x): the grid's own symmetry)
   grows the turned path: every vertex within 1e-9 m of the turned one, at the same times, the
   same K within 1e-9 of the largest K_I, and the same faces (measured: the vertices and times
   equal to the bit, K_II differing in its tenth digit on two rows of 93).
Set LAUNCH (e.g. "mpiexec -n 2") to run under it.
Usage: check_wall_junction.py RUPTURE INPUTS_DIR WORK_DIR"""
import csv
import json
import math
import os
import re
import shlex
import subprocess
import sys

import numpy as np

rupture, inputs, work = sys.argv[1], sys.argv[2], sys.argv[3]
launch = shlex.split(os.environ.get("LAUNCH", ""))
os.makedirs(work, exist_ok=True)
failures = []


def run(name, case=None):
    where = os.path.join(work, name)
    subprocess.run(launch + [rupture, "run", case or os.path.join(inputs, name + ".toml"), "-o", where,
                             "--overwrite", "--quiet"], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(where, "run.json")) as f:
        r = json.load(f)
    if r.get("status") != "completed":
        failures.append(f"{name}: status {r.get('status')}: {r.get('message')}")
    return where, r


def crack(r, name):
    return [c for c in r["cracks"] if c.get("interface") == name][0]


# 1. The same problem drawn two ways.
wall, wr = run("wall_junction")
bond, _ = run("bond_junction")
faces = crack(wr, "bond").get("lower_faces")
print("wall_junction: run.json cracks[bond].lower_faces =", faces)
if faces != [[0.0, "plate.below.bond"], [0.01, "plate.below.bond.below.cut"]]:
    failures.append(f"wall_junction: lower_faces {faces}: the face below should change at x = 10 mm")
last = list(csv.DictReader(open(os.path.join(wall, "crack_path_cut.csv"))))[-1]
if abs(float(last["x"]) - 0.01) > 1e-9 or abs(float(last["y"]) - 0.006) > 1e-9:
    failures.append(f"wall_junction: the cut ends at ({last['x']}, {last['y']}), not on the bond at (0.01, 0.006)")
for name in ("left", "right", "upper"):
    a = np.genfromtxt(os.path.join(wall, "stations", name + ".csv"), delimiter=",", names=True)
    b = np.genfromtxt(os.path.join(bond, "stations", name + ".csv"), delimiter=",", names=True)
    worst = max(np.abs(a[k] - b[k]).max() / max(np.abs(b[k]).max(), 1e-300) for k in ("ux", "uy", "vx", "vy"))
    print(f"station {name}: {len(a)} samples, largest difference from two bonded bodies {worst:.3g} "
          f"(of each column's largest value)")
    if len(a) != len(b) or worst > 1e-12:
        failures.append(f"wall_junction: station {name} differs from bond_junction's by {worst:.3g}")

# 2. A kinked crack that ends on an edge crack in its plate.
out, r = run("crack_into_wall")
ax, ay, bx, by = 0.015, -0.0028868, 0.04, 0.0115470  # the wall, drawn from its tip to the edge
rows = list(csv.DictReader(open(os.path.join(out, "crack_path_crack.csv"))))
right = [q for q in rows if q["tip"] == "1"]
left = [q for q in rows if q["tip"] == "0"]
jx, jy = float(right[-1]["x"]), float(right[-1]["y"])
ux, uy = (bx - ax) / math.hypot(bx - ax, by - ay), (by - ay) / math.hypot(bx - ax, by - ay)
s_j = (jx - ax) * ux + (jy - ay) * uy
off = abs(-(jx - ax) * uy + (jy - ay) * ux)
print(f"crack_into_wall: the right tip ends at ({jx * 1e3:.4f}, {jy * 1e3:.4f}) mm at "
      f"{float(right[-1]['time']) * 1e6:.2f} us, {off:.2e} m off the wall, {s_j * 1e3:.4f} mm along it; "
      f"first segment at {float(right[0]['angle']):.2f} degrees; {len(right)} segments")
if off > 1e-9 or not 0.0 < s_j < math.hypot(bx - ax, by - ay):
    failures.append(f"crack_into_wall: the right tip does not end on the wall ({off:.3g} m off, s = {s_j:.4g} m)")
faces = crack(r, "wall").get("upper_faces")
print("crack_into_wall: run.json cracks[wall].upper_faces =", faces)
if (not faces or len(faces) != 2 or faces[0] != [0.0, "plate.below.crack"] or faces[1][1] != "plate"
        or abs(faces[1][0] - s_j) > 1e-9):
    failures.append(f"crack_into_wall: upper_faces {faces}: should change from the crack's lower part to "
                    f"the part above it at s = {s_j:.6g} m")
lx = float(left[-1]["x"])
print(f"crack_into_wall: the left tip ends at x = {lx * 1e3:.3f} mm")
if abs(lx + 0.04) > 1e-9:
    failures.append(f"crack_into_wall: the left tip ends at x = {lx}, not on the left edge")
err = r.get("energy_balance_error_final")
print(f"crack_into_wall: energy_balance_error_final = {err}")
if err is None or abs(err) > 0.01:
    failures.append(f"crack_into_wall: energy balance error {err}")
# 4. The cut runs on along the wall into its tie.
tied, tr4 = run("crack_into_tied_wall")
rows4 = list(csv.DictReader(open(os.path.join(tied, "crack_path_crack.csv"))))
end4 = [q for q in rows4 if q["tip"] == "1"][-1]
wx0, wy0, wx1, wy1 = 0.015, -0.0028868, 0.03, 0.0057735
ex, ey = float(end4["x"]), float(end4["y"])
wl = math.hypot(wx1 - wx0, wy1 - wy0)
off4 = abs(-(ex - wx0) * (wy1 - wy0) / wl + (ey - wy0) * (wx1 - wx0) / wl)
print(f"crack_into_tied_wall: the right tip ends at ({ex * 1e3:.4f}, {ey * 1e3:.4f}) mm at "
      f"{float(end4['time']) * 1e6:.2f} us, {off4:.2e} m off the wall; faces {crack(tr4, 'wall').get('upper_faces')}")
if off4 > 1e-9:
    failures.append(f"crack_into_tied_wall: the right tip does not end on the wall ({off4:.3g} m off)")
normal = (-(wy1 - wy0) / wl, (wx1 - wx0) / wl)


def opening(a, b):
    A = np.genfromtxt(os.path.join(tied, "stations", a + ".csv"), delimiter=",", names=True)
    B = np.genfromtxt(os.path.join(tied, "stations", b + ".csv"), delimiter=",", names=True)
    return (A["ux"] - B["ux"]) * normal[0] + (A["uy"] - B["uy"]) * normal[1]


tie_open, wall_open = opening("above_tie", "below_tie"), opening("above_wall", "below_wall")
print(f"crack_into_tied_wall: opening across the wall's tie at most {tie_open.max() * 1e6:.3f} um, across its "
      f"crack {wall_open[-1] * 1e6:.3f} um at the end")
if tie_open.max() > 10e-6:
    failures.append(f"crack_into_tied_wall: the wall's tie opened by {tie_open.max() * 1e6:.1f} um (bound 10 um)")
if wall_open[-1] < 100e-6:
    failures.append(f"crack_into_tied_wall: the wall's crack opened by only {wall_open[-1] * 1e6:.1f} um")
if tr4.get("energy_balance_error_final") is None or abs(tr4["energy_balance_error_final"]) > 0.01:
    failures.append(f"crack_into_tied_wall: energy balance error {tr4.get('energy_balance_error_final')}")

# 3. Turned by 90 degrees.
text = open(os.path.join(inputs, "crack_into_wall.toml")).read()
text = text[text.index("title"):]


def turn(m):
    x, y = float(m.group(1)), float(m.group(2))
    return f"[{-y + 0.0!r}, {x!r}]"


text = re.sub(r"\[(-?[0-9.e-]+), (-?[0-9.e-]+)\]", turn, text)
# Boxes: min and max swap in x once turned.
text = text.replace("min = [0.1, -0.04]", "min = [-0.1, -0.04]").replace("max = [-0.1, 0.04]", "max = [0.1, 0.04]")
turned_case = os.path.join(work, "crack_into_wall_turned.toml")
with open(turned_case, "w") as f:
    f.write(text)
turned, tr = run("crack_into_wall_turned", turned_case)
rows_t = list(csv.DictReader(open(os.path.join(turned, "crack_path_crack.csv"))))
worst = 0.0
same = len(rows_t) == len(rows)
k_scale = max(abs(float(a["K_I"])) for a in rows)
for a, b in zip(rows, rows_t):
    worst = max(worst, abs(-float(a["y"]) - float(b["x"])), abs(float(a["x"]) - float(b["y"])))
    same = same and a["tip"] == b["tip"] and a["time"] == b["time"]
    same = same and all(abs(float(a[k]) - float(b[k])) <= 1e-9 * k_scale for k in ("K_I", "K_II"))
faces_t = crack(tr, "wall").get("upper_faces")
print(f"turned by 90 degrees: {len(rows_t)} rows against {len(rows)}, vertices within {worst:.3g} m of the turned "
      f"ones, times and K {'the same' if same else 'differ'}; faces {faces_t}")
if not same or worst > 1e-9:
    failures.append(f"turned by 90 degrees: the path differs ({worst:.3g} m; rows, times or K equal: {same})")
if not faces_t or [f[1] for f in faces_t] != [f[1] for f in faces] or abs(faces_t[-1][0] - faces[-1][0]) > 1e-9:
    failures.append(f"turned by 90 degrees: the wall's faces {faces_t} differ from {faces}")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("ok")
