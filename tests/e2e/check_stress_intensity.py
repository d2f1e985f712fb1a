#!/usr/bin/python3
"""Stress intensity factors from the interaction integral (docs/fracture.md) on a pre-crack under
slowly applied remote tension: examples/centre_crack_tension.toml widened to a plate 2b = 160 mm
wide (a / b = 0.125) and 200 mm tall, the crack 2a = 20 mm turned by beta = 0, 30, 45, 60 degrees
about the plate's centre, h = 1 mm (10 cells per a), read at the end (700 us, the load held since
600 us). The crack's centre sits 0.1 mm above the plate's (a line through particle centres, as
y = x is at 45 degrees on this lattice, would put particles on the crack). Against the inclined crack in a wide plate:
    K_I = sigma sqrt(pi a) cos^2(beta) F,  K_II = sigma sqrt(pi a) sin(beta) cos(beta) F
at both tips (the crack's frame turns with it: K_II > 0 at both), F = 1.0096 the Feddersen-Tada
width correction of the centre crack at a / b = 0.125 (Tada, Paris & Irwin, p. 5.2; applied to
both modes: its own size, 1 %, bounds what that leaves out). Checks, per beta and tip:
  - K_I and K_II within 5 % of sigma sqrt(pi a) F (the issue's bound; K_II in that unit too, as
    it vanishes at beta = 0);
  - J path independent: the three domains (radii 4, 6, 8 cells) within 3 % of their mean;
  - at beta = 0, J within 3 % of K_exact^2 / E' (J is the energy release rate G); at the other
    angles J / ((K_I^2 + K_II^2) / E') is printed, not checked: J reads 2 to 8 % above it on
    inclined cracks at 10 cells per a (docs/fracture.md, an open finding: at 45 degrees the
    worse tip's 6.4 % goes to 2.9 and 1.2 % at 20 and 40 cells per a), while K is within 1.5 %;
  - the two tips agree within 1 % (the problem's symmetry under a half turn);
  - the maximum hoop stress angle from the computed K within 3 degrees of the one from the exact
    K (the kink a growing tip would take).
Usage: check_stress_intensity.py RUPTURE WORK_DIR"""
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
sigma, a, b, E, nu = 10e6, 0.01, 0.08, 5.2e9, 0.34
Ep = E / (1 - nu * nu)
r = a / b
F = (1 - 0.025 * r * r + 0.06 * r ** 4) * math.sqrt(1 / math.cos(math.pi * r / 2))
K0 = sigma * math.sqrt(math.pi * a) * F


def hoop(KI, KII):
    if KII == 0:
        return 0.0
    return math.degrees(2 * math.atan((KI - math.sqrt(KI * KI + 8 * KII * KII)) / (4 * KII)))


failures = []
print(f"sigma sqrt(pi a) F = {K0:.6g} Pa m^1/2 (F = {F:.4f})")
print("beta tip K_I/ref K_II/ref (K_I-exact)/K0 (K_II-exact)/K0 J_spread J/(K^2/E') kink kink_exact")
for beta in [int(v) for v in os.environ.get('BETAS', '0 30 45 60').split()]:
    c, s = math.cos(math.radians(beta)), math.sin(math.radians(beta))
    out = os.path.join(work, f"beta_{beta}")
    cmd = [rupture, "run", example, "-o", out, "--overwrite", "--quiet",
           *WIDE,
           *crack(a, beta)]
    subprocess.run(cmd, check=True)
    d = np.genfromtxt(os.path.join(out, "stress_intensity_crack.csv"), delimiter=",", names=True)
    last = d[d["time"] == d["time"].max()]
    KIe, KIIe = K0 * c * c, K0 * s * c
    per_tip = []
    for tip in (0, 1):
        rows = last[last["tip"] == tip]
        J = rows["J"]
        outer = rows[rows["domain"] == rows["domain"].max()][0]
        KI, KII = outer["K_I"], outer["K_II"]
        spread = (J.max() - J.min()) / J.mean()
        JK = outer["J"] / ((KI * KI + KII * KII) / Ep)
        kink, kink_e = hoop(KI, KII), hoop(KIe, KIIe)
        per_tip.append((KI, KII))
        print(f"{beta:4d} {tip:3d} {KI / K0:.4f} {KII / K0:.4f} {(KI - KIe) / K0:+.4f} "
              f"{(KII - KIIe) / K0:+.4f} {spread:.4f} {JK:.4f} {kink:7.2f} {kink_e:7.2f}")
        if abs(KI - KIe) > 0.05 * K0:
            failures.append(f"beta {beta} tip {tip}: K_I {KI:.4g} vs {KIe:.4g}")
        if abs(KII - KIIe) > 0.05 * K0:
            failures.append(f"beta {beta} tip {tip}: K_II {KII:.4g} vs {KIIe:.4g}")
        if spread > 0.03:
            failures.append(f"beta {beta} tip {tip}: J over the domains spreads {spread:.3%}")
        Jexact = (KIe * KIe + KIIe * KIIe) / Ep
        if beta == 0 and abs(outer["J"] / Jexact - 1) > 0.03:
            failures.append(f"beta {beta} tip {tip}: J {outer['J']:.5g} vs K^2/E' {Jexact:.5g}")
        if abs(kink - kink_e) > 3.0:
            failures.append(f"beta {beta} tip {tip}: kink {kink:.2f} vs {kink_e:.2f} degrees")
    (a0, b0), (a1, b1) = per_tip
    if abs(a0 - a1) > 0.01 * K0 or abs(b0 - b1) > 0.01 * K0:
        failures.append(f"beta {beta}: the tips differ: K_I {a0:.5g} / {a1:.5g}, K_II {b0:.5g} / {b1:.5g}")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("ok")
