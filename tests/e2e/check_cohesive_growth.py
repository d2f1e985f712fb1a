#!/usr/bin/python3
"""A cohesive crack that grows (docs/fracture.md, "Cohesive cracks that grow"):
examples/cohesive_crack_growth.toml, an edge cut in a plate pulled in mode I, whose grown
segments carry the Xu-Needleman law (q = 1, r = 0: a potential law, so a point's work from rest
never exceeds phi_n, and a point that has let go, at |jump| = 5 delta_t, took all but
(1 + x) e^-x of it, x = 5 delta_t / delta_n = 11.66: 1e-4). Checks that could fail if the
physics were wrong:
  - energy: the cohesive work (dissipated + stored, run.json energy_cohesive) per unit of
    grown line is at most phi_n (no point can take more), and the dissipated part is at least
    phi_n (1 - 1e-4) per unit of grown line that has let go (the crack tracker's separated tip
    beyond the cut); the cut itself carries no cohesion;
  - the mode-I path stays on the cut's line (every vertex within one segment, h / 2);
  - the separated tip runs below the Rayleigh speed;
  - h and h / 2 give the same path within h, and grown lengths within 15 % (the zone, 7 mm,
    is resolved at both).
Usage: check_cohesive_growth.py RUPTURE WORK_DIR"""
import json
import math
import os
import subprocess
import sys

import numpy as np

rupture, work = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "..", "examples", "cohesive_crack_growth.toml")
os.makedirs(work, exist_ok=True)
phi_n, cut, y0, c_R = 200.0, 0.01, 1e-4, 1164.9
failures = []


def run(name, *sets):
    out = os.path.join(work, name)
    args = [rupture, "run", example, "-o", out, "--overwrite", "--quiet"]
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    path = np.genfromtxt(os.path.join(out, "crack_path_crack.csv"), delimiter=",", names=True)
    tip = np.genfromtxt(os.path.join(out, "crack_tip_crack.csv"), delimiter=",", names=True)
    return path, tip, json.load(open(os.path.join(out, "run.json")))


def check(name, h, path, tip, rec):
    grown = rec["cracks.crack.length"]
    separated = tip["tip_s"][-1] - cut
    work_ = rec["energy_cohesive"]["dissipated"] + rec["energy_cohesive"]["stored"]
    diss = rec["energy_cohesive"]["dissipated"]
    off = np.max(np.abs(path["y"] - y0))
    moving = tip[tip["tip_s"] > cut + 1e-9]
    speed = np.max(np.diff(tip["tip_s"]) / np.diff(tip["time"])) if len(moving) else 0.0
    # The speed over 4 samples (2 us): a sample's step is a node's crack time, whole segments.
    s4 = (tip["tip_s"][4:] - tip["tip_s"][:-4]) / (tip["time"][4:] - tip["time"][:-4])
    print(f"{name}: starts {rec['cracks.crack.initiation_time'] * 1e6:.2f} us, grown {grown * 1e3:.2f} mm, "
          f"separated {separated * 1e3:.2f} mm; cohesive work {work_:.4f} J/m = "
          f"{work_ / (phi_n * grown):.3f} phi_n x grown; dissipated {diss:.4f} J/m = "
          f"{diss / (phi_n * separated) if separated > 0 else math.nan:.3f} phi_n x separated; "
          f"path off the line by {off * 1e3:.3f} mm; separated tip speed over 2 us at most "
          f"{np.max(s4):.0f} m/s ({np.max(s4) / c_R:.2f} c_R)")
    if not grown >= 10 * h or not separated >= 4 * h:
        failures.append(f"{name}: grew {grown:.3g} m, separated {separated:.3g} m (the test needs growth)")
    if work_ > phi_n * grown * (1 + 1e-6):
        failures.append(f"{name}: cohesive work {work_:.5g} J/m above phi_n x grown length {phi_n * grown:.5g}")
    if diss < phi_n * separated * (1 - 1e-4) - 1e-9:
        failures.append(f"{name}: dissipated {diss:.5g} J/m below phi_n x separated length {phi_n * separated:.5g}")
    if off > 0.5 * h:
        failures.append(f"{name}: the mode-I path leaves the line by {off:.3g} m (bound h/2 = {0.5 * h} m)")
    if np.max(s4) >= c_R:
        failures.append(f"{name}: the separated tip ran at {np.max(s4):.0f} m/s, not below c_R")


h = 0.5e-3
base = run("base")
check("base (max_hoop)", h, *base)
fine = run("fine", f"grid.cell_size={h / 2!r}", "interface.crack.segments=40")
check("h/2", h / 2, *fine)
# h against h/2: every vertex of the coarse path within h of the fine one (over their common
# length; both are near-straight, so the distance is the y difference at the same x).
common = min(base[0]["x"].max(), fine[0]["x"].max())
fx, fy = fine[0]["x"], fine[0]["y"]
dev = max(abs(y - np.interp(x, fx, fy)) for x, y in zip(base[0]["x"], base[0]["y"]) if x <= common)
lengths = (base[2]["cracks.crack.length"], fine[2]["cracks.crack.length"])
print(f"h vs h/2: paths {dev * 1e3:.3f} mm apart over x <= {common * 1e3:.2f} mm (bound {h * 1e3:.1f}); "
      f"grown {lengths[0] * 1e3:.2f} / {lengths[1] * 1e3:.2f} mm")
if dev > h:
    failures.append(f"the paths at h and h/2 lie {dev:.3g} m apart (bound {h} m)")
if abs(lengths[0] - lengths[1]) > 0.15 * lengths[1]:
    failures.append(f"grown lengths {lengths[0]:.4g} and {lengths[1]:.4g} m differ by more than 15 %")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("cohesive crack growth: energy bounds, path and convergence hold")
