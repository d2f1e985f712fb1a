#!/usr/bin/python3
"""K_II of a crack pressed shut, with and without friction on its faces (docs/fracture.md, "Faces
in contact"): the plate of tests/e2e/check_stress_intensity.py (examples/centre_crack_tension.toml
widened to 160 x 200 mm, 2a = 20 mm at h = 1 mm, the crack turned by beta = 45 degrees) pushed
instead of pulled: -10 MPa on a 600 us smooth ramp, read at 300 us (half the load). The faces press
together with sigma_n = -sigma cos^2 beta and slide (tan beta = 1 exceeds the friction mu), so the
closed crack carries the shear the faces do not hold (the frictional closed flaw of the wing-crack
analyses, Horii & Nemat-Nasser 1986):
    K_I = 0,   K_II = -sigma sqrt(pi a) F (sin beta cos beta - mu cos^2 beta),
F = 1.0096 as in the open crack's test (Tada, Paris & Irwin p. 5.2). Checks, per mu and tip:
  - mu = 0: K_II within 5 % of the exact value (the issue's bound for K);
  - mu = 0.3: within 10 % (the friction's traction near the tip, within a cell, differs between
    the two tips of this lattice: -7 % and +9 % at 1 mm, -6 % and +9 % at 0.5 mm, so the bound is
    the model's, not the grid's); without the faces' contact term in the interaction integral
    (before 2026-12-06) the reading was 24-34 % high and moved with the domain;
  - the three domains (4, 6, 8 cells) within 2 % of their mean: the faces' shear enters through
    its face term, not through a domain-dependent error;
  - the domains read K_I < 0 at both tips: the faces press together (the pressure's term is left
    out of K_I, and growth reads such a tip as K_I = 0).
Usage: check_closed_crack.py RUPTURE WORK_DIR"""
import math
import os
import subprocess
import sys

import numpy as np

from wide_plate import WIDE, crack

rupture, work = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "..", "examples", "centre_crack_tension.toml")
os.makedirs(work, exist_ok=True)
sigma, a, F, beta = 10e6, 0.01, 1.0096, math.radians(45.0)
c, s = math.cos(beta), math.sin(beta)
failures = []
print("mu tip domain_mm K_I K_II exact_K_II error")
for mu, bound in ((0.0, 0.05), (0.3, 0.10)):
    out = os.path.join(work, f"mu_{mu:g}")
    subprocess.run([rupture, "run", example, "-o", out, "--overwrite", "--quiet",
                    *WIDE,
                    "--set", "loads.top.normal=-10e6", "--set", "loads.bottom.normal=-10e6",
                    *crack(a, 45), "--set", f"interface.crack.friction={mu!r}",
                    "--set", "time.end=300e-6", "--set", "output.crack_sample_interval=50e-6"],
                   check=True, stdout=subprocess.DEVNULL)
    k = np.genfromtxt(os.path.join(out, "stress_intensity_crack.csv"), delimiter=",", names=True)
    last = k[np.isclose(k["time"], k["time"].max())]
    exact = -0.5 * sigma * math.sqrt(math.pi * a) * F * (s * c - mu * c * c)  # half the load
    for tip in (0, 1):
        rows = last[last["tip"] == tip]
        if len(rows) != 3:
            failures.append(f"mu {mu}: tip {tip} has {len(rows)} readings at the end, expected 3")
            continue
        for r in rows:
            err = r["K_II"] / exact - 1.0
            print(f"{mu:3.1f} {tip:3d} {r['domain'] * 1e3:9.1f} {r['K_I'] / 1e6:8.4f} {r['K_II'] / 1e6:8.4f} "
                  f"{exact / 1e6:8.4f} {100 * err:+6.1f} %")
            if abs(err) > bound:
                failures.append(f"mu {mu} tip {tip} domain {r['domain']:.3g} m: K_II = {r['K_II']:.4g}, "
                                f"exact {exact:.4g} ({100 * err:+.1f} %, bound {100 * bound:.0f} %)")
            if r["K_I"] >= 0.0:
                failures.append(f"mu {mu} tip {tip}: K_I = {r['K_I']:.4g} >= 0 on a crack pressed shut")
        mean = rows["K_II"].mean()
        spread = np.abs(rows["K_II"] / mean - 1.0).max()
        if spread > 0.02:
            failures.append(f"mu {mu} tip {tip}: the domains' K_II differ by {100 * spread:.1f} % of their "
                            f"mean (bound 2 %)")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("a closed crack's K_II with and without friction within the bounds, the same on every domain")
