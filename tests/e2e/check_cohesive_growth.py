#!/usr/bin/python3
"""Cohesive cracks that grow (docs/fracture.md, "Cohesive cracks that grow"): an edge cut in a
plate pulled in mode I, whose grown segments carry a cohesive law, by two criteria:
  - examples/cohesive_crack_growth.toml: Xu-Needleman (q = 1, r = 0), growth = "energy" with
    G_c = phi_n;
  - examples/cohesive_strength_growth.toml: bilinear (G_Ic = G_IIc), growth = "cohesive" (a new
    segment once the last is past the law's peak traction; no toughness given).
Both laws take G_c from a point in any direction of opening at most (Xu-Needleman with q = 1,
r = 0 derives from a potential that never exceeds phi_n for an opening jump; the bilinear law's
radial damage with G_Ic = G_IIc spends G_c whatever the mode mix), and a point that has let go
has spent all of it (Xu-Needleman, at |jump| = 5 delta_t = 11.66 delta_n: all but
(1 + x) e^-x = 1e-4; bilinear, at full damage: all). Checks that could fail if the physics
were wrong, for each, at h and h/2:
  - energy: the cohesive work (dissipated + stored, run.json energy_cohesive) per unit of
    grown line is at most G_c, and the dissipated part at least G_c (1 - 0.005) per unit of
    grown line that has let go (the crack tracker's separated tip beyond the cut; the cut
    itself carries no cohesion). A point that has let go has spent all but 1e-4 of G_c, but
    the measured ratio moves by a few tenths of a percent with the step and the strength
    (Xu-Needleman at h/2, every Gauss point behind the tracked tip let go: 0.9976, 1.0016,
    1.0022, 0.9985 at cfl 0.4, 0.3, 0.2, 0.1; 1.0006 and 1.0148 with sigma_max 11.99 and
    12.01 MPa; the tie's earlier reach gave 0.9986 at cfl 0.1), so 0.5 % is allowed for the
    work of the points still in the zone, which the count by let-go length leaves out;
  - the mode-I crack (the separated part, up to the tracked tip) stays on the cut's line:
    every vertex within one segment, h / 2. The grown line beyond it, still cohesive (the
    zone's segments, laid where the end segment passed the law's peak), is printed, not
    checked: it wanders from run to run (bilinear at h/2: 0.108 mm off for the crack in every
    run below, the zone's line 1.027 and 0.340 mm with sigma_max 12.01 and 11.99 MPa);
  - the separated tip runs below the Rayleigh speed (over 2 us windows);
  - h and h / 2 give the same crack path within h (the separated parts), grown lengths within
    15 %, and the crack lets go at the same time within 1 us (the zone, about 7 mm, is
    resolved at both).
Usage: check_cohesive_growth.py RUPTURE WORK_DIR"""
import json
import os
import subprocess
import sys

import numpy as np

rupture, work = sys.argv[1], sys.argv[2]
examples = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples")
os.makedirs(work, exist_ok=True)
G_c, cut, y0, c_R = 200.0, 0.01, 1e-4, 1164.9
failures = []


def run(example, name, *sets):
    out = os.path.join(work, name)
    args = [rupture, "run", os.path.join(examples, example), "-o", out, "--overwrite", "--quiet"]
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    path = np.genfromtxt(os.path.join(out, "crack_path_crack.csv"), delimiter=",", names=True)
    tip = np.genfromtxt(os.path.join(out, "crack_tip_crack.csv"), delimiter=",", names=True)
    return path, tip, json.load(open(os.path.join(out, "run.json")))


def check(name, h, path, tip, rec):
    grown = rec["cracks.crack.length"]
    separated = tip["tip_s"][-1] - cut
    let_go = tip["time"][np.argmax(tip["tip_s"] > cut + 1e-9)] if separated > 0 else float("nan")
    work_ = rec["energy_cohesive"]["dissipated"] + rec["energy_cohesive"]["stored"]
    diss = rec["energy_cohesive"]["dissipated"]
    crack = path["x"] <= tip["tip_x"][-1] + 1e-9  # the separated part (the cut runs along x)
    off = np.max(np.abs(path["y"][crack] - y0))
    off_zone = np.max(np.abs(path["y"] - y0))
    # The separated tip's speed over 4 samples (2 us): it moves by whole segments.
    s4 = np.max((tip["tip_s"][4:] - tip["tip_s"][:-4]) / (tip["time"][4:] - tip["time"][:-4]))
    print(f"{name}: first segment {rec['cracks.crack.initiation_time'] * 1e6:.2f} us, lets go at "
          f"{let_go * 1e6:.2f} us; grown {grown * 1e3:.2f} mm, separated {separated * 1e3:.2f} mm; "
          f"cohesive work {work_:.4f} J/m = {work_ / (G_c * grown):.3f} G_c x grown; dissipated "
          f"{diss:.4f} J/m = {diss / (G_c * separated) if separated > 0 else float('nan'):.3f} G_c x "
          f"separated; crack off the line by {off * 1e3:.3f} mm (with the zone's line {off_zone * 1e3:.3f} mm); separated tip at most {s4:.0f} m/s "
          f"({s4 / c_R:.2f} c_R)")
    if not grown >= 10 * h or not separated >= 4 * h:
        failures.append(f"{name}: grew {grown:.3g} m, separated {separated:.3g} m (the test needs growth)")
    if work_ > G_c * grown * (1 + 1e-6):
        failures.append(f"{name}: cohesive work {work_:.5g} J/m above G_c x grown length {G_c * grown:.5g}")
    if diss < G_c * separated * (1 - 0.005) - 1e-9:
        failures.append(f"{name}: dissipated {diss:.5g} J/m below G_c x separated length {G_c * separated:.5g}")
    if off > 0.5 * h:
        failures.append(f"{name}: the mode-I crack leaves the line by {off:.3g} m (bound h/2 = {0.5 * h} m)")
    if s4 >= c_R:
        failures.append(f"{name}: the separated tip ran at {s4:.0f} m/s, not below c_R")
    return let_go


h = 0.5e-3
for example, label in (("cohesive_crack_growth.toml", "Xu-Needleman, energy"),
                       ("cohesive_strength_growth.toml", "bilinear, cohesive")):
    stem = example.split(".")[0]
    base = run(example, stem)
    fine = run(example, stem + "_fine", f"grid.cell_size={h / 2!r}", "interface.crack.segments=40")
    t_base = check(f"{label}, h", h, *base)
    t_fine = check(f"{label}, h/2", h / 2, *fine)
    # Both paths are near-straight: their distance is the y difference at the same x, over the
    # separated crack both have.
    common = min(base[1]["tip_x"][-1], fine[1]["tip_x"][-1])
    fx, fy = fine[0]["x"], fine[0]["y"]
    dev = max(abs(y - np.interp(x, fx, fy)) for x, y in zip(base[0]["x"], base[0]["y"]) if x <= common)
    lengths = (base[2]["cracks.crack.length"], fine[2]["cracks.crack.length"])
    print(f"{label}: h vs h/2 cracks {dev * 1e3:.3f} mm apart over x <= {common * 1e3:.2f} mm (bound "
          f"{h * 1e3:.1f}); grown {lengths[0] * 1e3:.2f} / {lengths[1] * 1e3:.2f} mm; lets go at "
          f"{t_base * 1e6:.2f} / {t_fine * 1e6:.2f} us")
    if dev > h:
        failures.append(f"{label}: the paths at h and h/2 lie {dev:.3g} m apart (bound {h} m)")
    if abs(lengths[0] - lengths[1]) > 0.15 * lengths[1]:
        failures.append(f"{label}: grown lengths {lengths[0]:.4g} and {lengths[1]:.4g} m differ by more than 15 %")
    if not abs(t_base - t_fine) <= 1e-6:
        failures.append(f"{label}: lets go at {t_base:.4g} and {t_fine:.4g} s at h and h/2 (bound 1 us)")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("cohesive crack growth: energy bounds, path and convergence hold")
