#!/usr/bin/python3
"""A crack that ends on an interface (a T-junction; docs/interfaces.md): tests/inputs/t_junction.toml,
a crack drawn in the right of two plates from their bond at x = 0 to (10, 0) mm, the bond a strong
Xu-Needleman law that stays intact, the plates pulled by 10 MPa at the top and bottom. The bond's
face on the right plate lies on the two parts the crack splits that plate into: below the crack's
end on one velocity field, above it on the other. An intact bond makes the two plates one body,
so the crack's tip must read what the same crack drawn in one plate reads
(tests/inputs/t_junction_monolith.toml). Checks:
  - `rupture check` and run.json name the face's two parts and where the face changes (at the
    crack's end, arc length 0.1 m along the bond);
  - K_I and K_II of the tip over time (outer domain, 8 cells), from 100 us (5 MPa pulled) to the
    end (200 us), within 1 % of the one-plate crack's K_I at that time. What may differ: the bond's
    compliance, and the junction, smeared over the part of the line its node holds (the node moves
    half with each part). The bond's segments are half a cell (the junction smeared over half a
    cell each side): measured 0.26 % at most; with segments of one cell 2.2 %, and 1.2 % at
    h = 0.5 mm with half-millimetre segments (first order in the segment). Control: the crack
    moved 5 mm off the bond (its tie ending there) reads the one-plate K to 0.03 %. K_II vanishes
    by the mirror symmetry y -> -y;
  - the bond stays intact and the run ends normally.
With the whole face on one part (the other part's edge then free of the bond), the tip read K_I
2.2 times the one-plate crack's at 200 us and K_II 0.17 of it, and the bond cracked (measured
once by hand): this is what the checks detect.
Usage: check_t_junction.py RUPTURE INPUTS_DIR WORK_DIR"""
import json
import os
import subprocess
import sys

import numpy as np

rupture, inputs, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
failures = []

check = subprocess.run([rupture, "check", os.path.join(inputs, "t_junction.toml")],
                       capture_output=True, text=True)
line = [l for l in check.stdout.splitlines() if l.startswith("interface bond:")]
print(line[0] if line else check.stdout + check.stderr)
want = "lower face on right.below.crack from s = 0 m right from s = 0.1 m"
if check.returncode != 0 or not line or want not in line[0]:
    failures.append(f"rupture check: expected '{want}' on the bond's line (rc {check.returncode})")


def run(name):
    out = os.path.join(work, name)
    subprocess.run([rupture, "run", os.path.join(inputs, name + ".toml"), "-o", out, "--overwrite",
                    "--quiet"], check=True, stdout=subprocess.DEVNULL)
    d = np.genfromtxt(os.path.join(out, "stress_intensity_crack.csv"), delimiter=",", names=True)
    with open(os.path.join(out, "run.json")) as f:
        return d, json.load(f)


def right_tip(d):
    """The outer domain's rows of the tip at the crack's right end (x = 10 mm), by time."""
    rows = d[d["domain"] == d["domain"].max()]
    tip = rows["tip"][np.argmax(rows["x"])]
    rows = rows[rows["tip"] == tip]
    return rows[np.argsort(rows["time"])]


t_d, t_json = run("t_junction")
m_d, m_json = run("t_junction_monolith")
bond = [c for c in t_json["cracks"] if c.get("interface") == "bond"][0]
faces = bond.get("lower_faces")
print("run.json cracks[bond].lower_faces =", faces)
if faces != [[0.0, "right.below.crack"], [0.1, "right"]]:
    failures.append(f"run.json lower_faces {faces}")
if t_json.get("status") != "completed":
    failures.append(f"status {t_json.get('status')}")
if bond.get("initiated"):
    failures.append("the bond cracked")
T, M = right_tip(t_d), right_tip(m_d)
print("time_us K_I_T K_I_one K_I_T/K_I_one K_II_T/K_I_one K_II_one/K_I_one")
worst = 0.0
for row in T:
    t = row["time"]  # the two runs' steps differ (the bond's stiffness bounds this one's)
    if t < M["time"][0] or t > M["time"][-1]:
        continue
    KI, KII = np.interp(t, M["time"], M["K_I"]), np.interp(t, M["time"], M["K_II"])
    ratio = row["K_I"] / KI
    print(f"{t * 1e6:7.1f} {row['K_I']:.5g} {KI:.5g} {ratio:.4f} "
          f"{row['K_II'] / KI:+.4f} {KII / KI:+.4f}")
    if t >= 100e-6 - 1e-9:
        worst = max(worst, abs(ratio - 1), abs(row["K_II"] - KII) / KI)
print(f"largest difference from 100 us on: {worst:.4f} of K_I")
if worst > 0.01:
    failures.append(f"the tip differs from the one-plate crack's by {worst:.2%} of K_I (bound 1 %)")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("ok")
