#!/usr/bin/python3
"""Dynamic branching (examples/dynamic_branching.toml, docs/validation.md): the notch tip splits once,
where Yoffe's criterion says, and the two branches are mirror images.
- crack_path_notch.csv has one split row (end 2 or 3) followed by the two branches' first
  segments (tips 2 and 3); run.json and the CLI give cracks.notch.branches = 1;
- the split comes at the first growth step at which the tip's speed (recomputed here from the
  path's rows: the path over the last 8 cells, the outer J domain's radius, over the time since
  that stretch began) reaches Yoffe's speed, which this check computes on its own from Freund's
  running mode-I field (the lowest speed at which the hoop stress's curvature at theta = 0 turns
  positive: 0.604 c_s for nu = 0.2 in plane strain), and the half angle is where that field's hoop
  stress is largest at the speed (a scan of theta here, within 0.2 degrees);
- the branches run to the plate's right edge, mirror images about y = 0 within 1e-6 of a cell;
- the energy balance closes within 1 %.
With options after "--" (more --set, e.g. nested levels round the path) the same checks hold, and
the split is compared with the plain example's (run into WORK_DIR/uniform): the same place within
a cell, its time within 0.5 us (two crossings of a 1 mm coarse cell by the dilatational wave,
0.26 us each: the load reaches the crack through the coarse level), the branches' ends within
two cells.
Usage: check_branching.py RUPTURE WORK_DIR [-- OPTION...]"""
import json
import math
import os
import subprocess
import sys

import numpy as np

rupture, work = sys.argv[1:3]
extra = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "..", "examples", "dynamic_branching.toml")
h = 0.5e-3
r = subprocess.run([rupture, "run", example, "-o", work, "--overwrite", "--set", "time.end=65e-6", *extra],
                   capture_output=True, text=True)
if r.returncode != 0:
    sys.exit(f"FAIL: run exited {r.returncode}:\n{r.stderr}")
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


run = json.load(open(os.path.join(work, "run.json")))
check(run["cracks.notch.branches"] == 1, f"run.json cracks.notch.branches = {run['cracks.notch.branches']} (1)")
check("crack.notch.branches=1" in r.stdout.splitlines(), "CLI line crack.notch.branches=1")
d = np.genfromtxt(os.path.join(work, "crack_path_notch.csv"), delimiter=",", names=True)
split = np.nonzero(d["end"] >= 2)[0]
check(len(split) == 1, f"{len(split)} split rows (1)")
if failures:
    sys.exit(1)
i = int(split[0])
check(d["end"][i] == 3 and d["length"][i] == 0.0 and list(d["tip"][i + 1:i + 3]) == [2, 3],
      "the split (at the line's end, length 0) is followed by tips 2 and 3's first segments")

# Freund's running mode-I field (1990, eq. 4.3.11), written again here.
E, nu, rho = 32e9, 0.2, 2450.0
mu = E / (2 * (1 + nu))
cs, cd = math.sqrt(mu / rho), math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho)


def hoop(theta, v):
    ad, as_ = math.sqrt(1 - (v / cd) ** 2), math.sqrt(1 - (v / cs) ** 2)
    D = 4 * ad * as_ - (1 + as_ ** 2) ** 2
    c, s = math.cos(theta), math.sin(theta)
    td, ts = math.atan2(ad * s, c), math.atan2(as_ * s, c)
    gd, gs = math.sqrt(c * c + (ad * s) ** 2), math.sqrt(c * c + (as_ * s) ** 2)
    xx = ((1 + as_ ** 2) * (1 + 2 * ad ** 2 - as_ ** 2) * math.cos(td / 2) / math.sqrt(gd)
          - 4 * ad * as_ * math.cos(ts / 2) / math.sqrt(gs)) / D
    yy = (-(1 + as_ ** 2) ** 2 * math.cos(td / 2) / math.sqrt(gd) + 4 * ad * as_ * math.cos(ts / 2) / math.sqrt(gs)) / D
    xy = 2 * ad * (1 + as_ ** 2) * (math.sin(td / 2) / math.sqrt(gd) - math.sin(ts / 2) / math.sqrt(gs)) / D
    return xx * s * s + yy * c * c - 2 * xy * s * c


lo, hi = 0.3 * cs, 0.9 * cs
for _ in range(60):
    mid = 0.5 * (lo + hi)
    lo, hi = (lo, mid) if hoop(1e-3, mid) > hoop(0.0, mid) else (mid, hi)
v_yoffe = 0.5 * (lo + hi)
check(abs(v_yoffe / cs - 0.604) < 0.002, f"Yoffe's speed {v_yoffe:.1f} m/s = {v_yoffe / cs:.4f} c_s (0.604)")

# The tip's speed at each of its growth steps before the split, as the criterion measures it.
own = (d["tip"] < 2) & (d["end"] == 1)
t, length = d["time"][own], d["length"][own]


def speed_at(now, rows):
    grown = 0.0
    for j in range(rows - 1, -1, -1):
        grown += length[j]
        if grown >= 8 * h * (1 - 1e-9):
            return grown / (now - t[j - 1]) if j >= 1 and now > t[j - 1] else 0.0
    return 0.0


ts = d["time"][i]
before = [speed_at(tk, k) for k, tk in enumerate(t) if tk < ts]
v = speed_at(ts, int(np.sum(t < ts)))
check(v >= v_yoffe and all(b < v_yoffe for b in before),
      f"split at {ts * 1e6:.2f} us, x = {d['x'][i] * 1e3:.2f} mm: speed {v:.1f} m/s >= Yoffe's, "
      f"every growth step before below it (largest {max(before):.1f} m/s)")
angles = np.linspace(0.0, math.pi / 2, 9001)
best = math.degrees(angles[int(np.argmax([hoop(a, v) for a in angles]))])
check(abs(d["angle"][i] - best) < 0.2, f"half angle {d['angle'][i]:.2f} deg, largest hoop stress at {best:.2f} deg")

left, right = d[(d["tip"] == 2) & (d["end"] < 2)], d[(d["tip"] == 3) & (d["end"] < 2)]
check(left["x"][-1] >= 0.1 - 1e-9 and right["x"][-1] >= 0.1 - 1e-9,
      f"both branches reach the right edge (y = {left['y'][-1] * 1e3:.2f}, {right['y'][-1] * 1e3:.2f} mm)")
n = min(len(left), len(right))
mismatch = max(np.max(np.abs(left["x"][:n] - right["x"][:n])), np.max(np.abs(left["y"][:n] + right["y"][:n])))
check(len(left) == len(right) and mismatch < 1e-6 * h,
      f"the branches are mirror images: {len(left)} and {len(right)} vertices, largest mismatch {mismatch:.2e} m")
check(run["energy_balance_error"] < 0.01, f"energy balance error {run['energy_balance_error']:.4f} (< 0.01)")

if extra:
    plain = os.path.join(work, "uniform")
    subprocess.run([rupture, "run", example, "-o", plain, "--overwrite", "--quiet", "--set", "time.end=65e-6"],
                   check=True, stdout=subprocess.DEVNULL)
    u = np.genfromtxt(os.path.join(plain, "crack_path_notch.csv"), delimiter=",", names=True)
    j = int(np.nonzero(u["end"] >= 2)[0][0])
    check(abs(d["x"][i] - u["x"][j]) <= h and abs(d["y"][i] - u["y"][j]) <= h,
          f"split at ({d['x'][i] * 1e3:.2f}, {d['y'][i] * 1e3:.2f}) mm, the plain example's at "
          f"({u['x'][j] * 1e3:.2f}, {u['y'][j] * 1e3:.2f}) mm (within a cell)")
    check(abs(d["time"][i] - u["time"][j]) <= 0.5e-6,
          f"split at {d['time'][i] * 1e6:.2f} us, the plain example's at {u['time'][j] * 1e6:.2f} us (within 0.5 us)")
    for label in (2, 3):
        a = d[(d["tip"] == label) & (d["end"] < 2)]
        b = u[(u["tip"] == label) & (u["end"] < 2)]
        check(abs(a["y"][-1] - b["y"][-1]) <= 2 * h,
              f"branch {label} ends at y = {a['y'][-1] * 1e3:.2f} mm, the plain example's at {b['y'][-1] * 1e3:.2f} mm "
              f"(within two cells)")
sys.exit(1 if failures else 0)
