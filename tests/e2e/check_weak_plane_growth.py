#!/usr/bin/python3
"""The reference problem with its weak plane replaced by a crack that may leave it
(examples/rosakis1999_growth.toml; docs/fracture.md, "A weak plane ahead"). The edge crack is
loaded in shear, pressed shut (the domains read K_I < 0, so the criterion takes K_I+ = 0: pure
mode II). Running along the plane takes G_0 = K_II^2 / E' against the plane's G_c,p = 26.1
J/m^2; kinking at theta_c = -/+70.53 degrees takes G(theta_c) = (4/3) G_0 against the bulk's
G_c. So the crack must stay on the plane iff G_c,p / G_c < 3/4, i.e. G_c > 34.8 J/m^2. Checks
that could fail if the physics or its plumbing were wrong, at h = 1 mm:
  - G_c = 36 J/m^2 (just tougher than the threshold): every grown vertex on y = 0 exactly, the
    crack runs intersonic (between c_S and c_D: the reference problem's regime), run.json's
    initial_angle is 0;
  - G_c = 34 J/m^2 (just below): the first segment at 70.53 degrees (the sign of K_II: upward),
    initiating at the same time as the run on the plane (the same G_0 reached the first
    threshold), and the crack leaves the plane for good: its end more than 5 mm above it, its
    chord from the old tip within 20 degrees of theta_c.
Usage: check_weak_plane_growth.py RUPTURE WORK_DIR"""
import json
import math
import os
import subprocess
import sys

import numpy as np

rupture, work = sys.argv[1], sys.argv[2]
example = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "rosakis1999_growth.toml")
os.makedirs(work, exist_ok=True)
tip0, theta_c = 0.025, math.degrees(2.0 * math.atan(-1.0 / math.sqrt(2.0)))  # -70.53 degrees
E, nu, rho = 5.2e9, 0.34, 1246.0  # Homalite (the example's material), plane strain
c_S = math.sqrt(E / (2.0 * (1.0 + nu)) / rho)
c_D = math.sqrt(E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)) / rho)
failures = []


def run(name, g_c):
    out = os.path.join(work, name)
    subprocess.run([rupture, "run", example, "-o", out, "--overwrite", "--quiet", "--set", "grid.cell_size=1e-3",
                    "--set", f"interface.notch.fracture_energy={g_c}"], check=True, stdout=subprocess.DEVNULL)
    path = np.genfromtxt(os.path.join(out, "crack_path_notch.csv"), delimiter=",", names=True)
    return path, json.load(open(os.path.join(out, "run.json")))


def expect(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


stay, rs = run("stays", 36.0)
kink, rk = run("kinks", 34.0)
speed = rs["crack.sustained_speed"]  # the crack tracker of the one crack, as on the CLI
expect(len(stay) > 10 and np.all(stay["y"] == 0.0),
       f"G_c = 36: {len(stay)} segments, all on y = 0 (largest |y| {np.max(np.abs(stay['y'])):.3g} m)")
expect(rs["cracks.notch.initial_angle"] == 0.0, f"G_c = 36: initial_angle {rs['cracks.notch.initial_angle']}")
expect(c_S < speed < c_D, f"G_c = 36: sustained speed {speed:.0f} m/s between c_S {c_S:.0f} and c_D {c_D:.0f}")
first = math.degrees(math.atan2(kink["y"][0], kink["x"][0] - tip0))
expect(abs(abs(first) - abs(theta_c)) < 0.01 and first > 0,
       f"G_c = 34: first segment at {first:.3f} degrees (theta_c {-theta_c:.3f}, upward: K_II < 0)")
expect(abs(rk["cracks.notch.initiation_time"] - rs["cracks.notch.initiation_time"]) < 1e-12,
       f"G_c = 34 and 36 initiate together: {rk['cracks.notch.initiation_time'] * 1e6:.3f} / "
       f"{rs['cracks.notch.initiation_time'] * 1e6:.3f} us")
chord = math.degrees(math.atan2(kink["y"][-1], kink["x"][-1] - tip0))
expect(kink["y"][-1] > 5e-3 and abs(chord + theta_c) < 20.0,
       f"G_c = 34: end {kink['y'][-1] * 1e3:.2f} mm above the plane, chord {chord:.1f} degrees")
if failures:
    sys.exit(f"{len(failures)} check(s) failed")
