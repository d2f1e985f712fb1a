#!/usr/bin/python3
"""A crack that grows into a bond between two plates (docs/fracture.md "Junctions"):
tests/inputs/bond_junction.toml, a cut run up at 500 m/s from the lower plate's bottom edge to
the intact bond with the upper plate, which it reaches at 8 us; the lower plate's bottom edge is
pulled down, so the two pieces the cut leaves hang on the bond. The bond's lower face lies on
the cut's two fields, left and right of the junction. Checks:
  - the run ends normally; the cut's path ends on the bond (y = 6 mm) at x = 10 mm, reached at
    8 us (prescribed: 4 mm at 500 m/s, in half-cell segments), and the bond stays intact;
  - run.json gives the bond's lower face on the piece left of x = 10 mm ("lower") and on the one
    right of it ("lower.below.cut");
  - the two pieces move as mirror images (the problem is symmetric about x = 10 mm): at every
    station sample the left station's v_y equals the right one's and v_x is its opposite, within
    1e-6 of the largest speed;
  - they hang on the bond: from 8 us on, the vertical displacement at the three stations (each
    piece, the upper plate) within 2 % (of its largest value) of the same run with the cut drawn
    to the bond from the start (tests/inputs/bond_junction_drawn.toml; measured 0.31 %, 0.31 %
    and 0.69 %; against a plate not cut at all: 0.90 % and 3.4 %);
  - the energy balance closes to 1 % (run.json energy_balance_error_final; measured 0.026 %).
With the bond's whole lower face on the left piece (the right one then free of the bond: measured
once by hand), the displacements differ from the drawn cut's by 25 % (left), 58 % (right) and
76 % (upper): this is what the checks detect.
Set LAUNCH (e.g. "mpiexec -n 2") to run under it.
Usage: check_bond_junction.py RUPTURE INPUTS_DIR WORK_DIR"""
import csv
import json
import os
import shlex
import subprocess
import sys

import numpy as np

rupture, inputs, work = sys.argv[1], sys.argv[2], sys.argv[3]
launch = shlex.split(os.environ.get("LAUNCH", ""))
os.makedirs(work, exist_ok=True)
out, ref = os.path.join(work, "grown"), os.path.join(work, "drawn")
for name, where in (("bond_junction", out), ("bond_junction_drawn", ref)):
    subprocess.run(launch + [rupture, "run", os.path.join(inputs, name + ".toml"), "-o", where,
                             "--overwrite", "--quiet"], check=True, stdout=subprocess.DEVNULL)
failures = []
with open(os.path.join(out, "run.json")) as f:
    run = json.load(f)
if run.get("status") != "completed":
    failures.append(f"status {run.get('status')}: {run.get('message')}")
bond = [c for c in run["cracks"] if c.get("interface") == "bond"][0]
if bond.get("initiated"):
    failures.append("the bond cracked")
faces = bond.get("lower_faces")
print("run.json cracks[bond].lower_faces =", faces)
if faces != [[0.0, "lower"], [0.01, "lower.below.cut"]]:
    failures.append(f"run.json lower_faces {faces}: the bond's face should change at x = 10 mm")
err = run.get("energy_balance_error_final")
print(f"energy_balance_error_final = {err}")
if err is None or abs(err) > 0.01:
    failures.append(f"energy balance error {err}")
path = list(csv.DictReader(open(os.path.join(out, "crack_path_cut.csv"))))
last = path[-1]
x, y, t = float(last["x"]), float(last["y"]), float(last["time"])
print(f"the cut ends at ({x * 1e3:.4f}, {y * 1e3:.4f}) mm, laid at {t * 1e6:.3f} us, {len(path)} rows")
if abs(x - 0.01) > 1e-9 or abs(y - 0.006) > 1e-9:
    failures.append(f"the cut ends at ({x}, {y}), not on the bond at (0.01, 0.006)")
if not 7.5e-6 <= t <= 8.5e-6:
    failures.append(f"the cut reached the bond at {t * 1e6:.3f} us, not at 8 us")


def station(run, name):
    return np.genfromtxt(os.path.join(run, "stations", name + ".csv"), delimiter=",", names=True)


L, R, U = station(out, "left"), station(out, "right"), station(out, "upper")
vmax = max(np.abs(L["vy"]).max(), np.abs(L["vx"]).max(), 1e-30)
mirror = max(np.abs(L["vy"] - R["vy"]).max(), np.abs(L["vx"] + R["vx"]).max()) / vmax
print(f"left/right mirror difference: {mirror:.3g} of the largest speed {vmax:.4g} m/s")
if mirror > 1e-9:
    failures.append(f"the pieces are not mirror images: {mirror:.3g}")
print("time_us uy_left uy_upper (grown) uy_left uy_upper (drawn), um")
D = {n: station(ref, n) for n in ("left", "right", "upper")}
for i in range(0, len(L), 4):
    print(f"{L['time'][i] * 1e6:6.1f} {L['uy'][i] * 1e6:+.4f} {U['uy'][i] * 1e6:+.4f} "
          f"{D['left']['uy'][i] * 1e6:+.4f} {D['upper']['uy'][i] * 1e6:+.4f}")
for name, S in (("left", L), ("right", R), ("upper", U)):
    T = D[name]
    late = S["time"] >= 8e-6 - 1e-12
    n = min(len(S), len(T))
    late = late[:n]
    diff = np.abs(S["uy"][:n][late] - T["uy"][:n][late]).max() / np.abs(T["uy"]).max()
    print(f"{name}: u_y from 8 us on within {diff:.3%} of the drawn cut's")
    if diff > 0.02:
        failures.append(f"{name}: u_y differs from the drawn cut's by {diff:.2%} (bound 2 %)")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("ok")
