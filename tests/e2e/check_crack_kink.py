#!/usr/bin/python3
"""The first growth step of an inclined crack against the maximum hoop stress prediction
(docs/fracture.md, "Growth"): the plate of tests/e2e/check_stress_intensity.py
(examples/centre_crack_tension.toml widened to 160 x 200 mm, 2a = 20 mm, h = 1 mm, remote tension
sigma = 10 MPa on a 600 us smooth ramp) with the crack turned by beta = 0, 30, 45, 60 degrees and
growth = "max_hoop". K_Ic is half of the exact hoop stress intensity K_eq(beta) at full load, so
the tips start to grow near 300 us (half the load, where the ramp is quasi-static). Against the
exact K of the inclined crack (K_I = sigma sqrt(pi a) F cos^2 beta, K_II = sigma sqrt(pi a) F
sin beta cos beta; F = 1.0096, Tada-Paris-Irwin p. 5.2):
  - each tip's first segment turns from the crack by theta = 2 atan[(1 - sqrt(1 + 8 (K_II/K_I)^2))
    / (4 K_II/K_I)] within 3 degrees (-43.2, -53.1, -60.0 at 30, 45, 60; run.json
    cracks.crack.initial_angle is the first tip's);
  - growth starts within 3 % of the time the exact K_eq reaches K_Ic on the ramp;
  - beta = 0 (symmetric mode I), run on until each tip has grown 10 mm or more: every path vertex
    within one segment (half a cell) of the crack's axis, and the two tips mirror images of each
    other within one segment.
With LOAD=compression the edges are pushed instead of pulled (-10 MPa): the crack is pressed
shut (frictionless contact), its faces cannot carry a negative K_I, and it is the closed flaw of
the wing-crack analyses (Horii & Nemat-Nasser 1986): K_I = 0, K_II = -sigma sqrt(pi a) F sin beta
cos beta. Each tip must start where its shear alone reaches the toughness (K_eq = 2/sqrt3 |K_II|
half of its full-load value, within 3 %), kinked by +70.53 degrees (within 3), while the domains
read a negative K_I at the start (the faces' pressure: so the test needs the closed tip to grow).
With FRICTION=mu (compression only) the faces rub with Coulomb friction mu while they slide: the
shear they do not hold drives the tip, K_II = -sigma sqrt(pi a) F (sin beta cos beta - mu cos^2
beta) (the frictional closed flaw; the friction's traction enters K_II through the faces' contact
term of the interaction integral, docs/fracture.md "Faces in contact"), and the start is checked
against that K_II reaching the toughness.
Usage: check_crack_kink.py RUPTURE WORK_DIR (BETAS: the angles, default "0 30 45 60"; LOAD:
"tension", the default, or "compression"; FRICTION: 0 by default)"""
import json
import math
import os
import subprocess
import sys

import numpy as np

from wide_plate import CENTRE_Y, WIDE, crack

rupture, work = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "..", "examples", "centre_crack_tension.toml")
os.makedirs(work, exist_ok=True)
sigma, a, b, h, rise = 10e6, 0.01, 0.08, 1e-3, 600e-6
r = a / b
F = (1 - 0.025 * r * r + 0.06 * r ** 4) * math.sqrt(1 / math.cos(math.pi * r / 2))
K0 = sigma * math.sqrt(math.pi * a) * F


def hoop_angle(KI, KII):
    return 0.0 if KII == 0 else 2 * math.atan((KI - math.sqrt(KI * KI + 8 * KII * KII)) / (4 * KII))


def hoop_intensity(KI, KII, t):
    c = math.cos(t / 2)
    return c * (KI * c * c - 1.5 * KII * math.sin(t))


def ramp_time(fraction):
    """The time the smooth ramp tau - sin(2 pi tau)/(2 pi) reaches `fraction` (bisection)."""
    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if mid - math.sin(2 * math.pi * mid) / (2 * math.pi) < fraction else (lo, mid)
    return 0.5 * (lo + hi) * rise


failures = []
closed = os.environ.get("LOAD", "tension") == "compression"
print("beta tip initiation_us expected_us angle_deg exact_deg")
for beta in [int(v) for v in os.environ.get("BETAS", "0 30 45 60").split()]:
    c, s = math.cos(math.radians(beta)), math.sin(math.radians(beta))
    # Pressed shut: K_I = 0 (contact), and the shear's sign turns with the load's.
    mu = float(os.environ.get("FRICTION", "0"))
    KI, KII = (0.0, -K0 * (s * c - mu * c * c)) if closed else (K0 * c * c, K0 * s * c)
    theta = hoop_angle(KI, KII)
    Kc = 0.5 * hoop_intensity(KI, KII, theta)
    t_expected = ramp_time(0.5)
    end = 345e-6 if beta == 0 else 315e-6
    y0 = CENTRE_Y
    out = os.path.join(work, f"beta_{beta}")
    subprocess.run([rupture, "run", example, "-o", out, "--overwrite", "--quiet",
                    *WIDE,
                    *crack(a, beta), "--set", 'interface.crack.growth="max_hoop"',
                    "--set", f"interface.crack.toughness={Kc!r}", "--set", f"time.end={end!r}",
                    "--set", "output.crack_sample_interval=5e-6",
                    *(["--set", "loads.top.normal=-10e6", "--set", "loads.bottom.normal=-10e6",
                       "--set", f"interface.crack.friction={mu!r}"] if closed else [])],
                   check=True, stdout=subprocess.DEVNULL)
    d = np.genfromtxt(os.path.join(out, "crack_path_crack.csv"), delimiter=",", names=True, ndmin=1)
    record = json.load(open(os.path.join(out, "run.json")))
    for end_ in (0, 1):
        rows = d[d["end"] == end_]
        if len(rows) == 0:
            failures.append(f"beta {beta}: the tip at end {end_} did not grow")
            continue
        first = rows[0]
        print(f"{beta:4d} {end_:3d} {first['time'] * 1e6:10.2f} {t_expected * 1e6:10.2f} "
              f"{first['angle']:8.2f} {math.degrees(theta):8.2f}")
        if abs(first["angle"] - math.degrees(theta)) > 3.0:
            failures.append(f"beta {beta} end {end_}: first segment at {first['angle']:.2f} deg, "
                            f"the maximum hoop stress direction is {math.degrees(theta):.2f} (bound 3)")
        if abs(first["time"] - t_expected) > 0.03 * t_expected:
            failures.append(f"beta {beta} end {end_}: growth began at {first['time'] * 1e6:.2f} us, "
                            f"K_eq reaches K_Ic at {t_expected * 1e6:.2f} us (bound 3 %)")
    if closed and len(d):
        # The domains' K_I just before the first segment: negative (the faces press together),
        # so the start is the closed tip's, not that of a K_I risen through zero.
        k = np.genfromtxt(os.path.join(out, "stress_intensity_crack.csv"), delimiter=",", names=True)
        before = k[k["time"] < d["time"].min()]
        last = before[before["time"] == before["time"].max()] if len(before) else before
        if len(last) == 0 or last["K_I"].max() >= 0.0:
            failures.append(f"beta {beta}: the domains read K_I >= 0 before the start "
                            f"({last['K_I'].max() if len(last) else 'no reading'}): the tip was not pressed shut")
        else:
            print(f"   {beta}: K_I read before the start {last['K_I'].min() / 1e6:.3f} to "
                  f"{last['K_I'].max() / 1e6:.3f} MPa m^1/2, K_II {last['K_II'].mean() / 1e6:.3f} "
                  f"(exact {KII * 0.5 / 1e6:.3f} at half load)")
    angle = record["cracks.crack.initial_angle"]
    if abs(angle - math.degrees(theta)) > 3.0:
        failures.append(f"beta {beta}: run.json cracks.crack.initial_angle = {angle:.2f}, expected "
                        f"{math.degrees(theta):.2f} within 3")
    if beta == 0:
        tips = [d[d["end"] == e] for e in (0, 1)]
        grown = [len(t) * 0.5 * h for t in tips]
        off = max(np.abs(t["y"] - y0).max() for t in tips if len(t))
        print(f"   0: grown {grown[0] * 1e3:.1f} and {grown[1] * 1e3:.1f} mm, largest distance from the "
              f"axis {off * 1e3:.3f} mm (bound {0.5 * h * 1e3:.1f})")
        if min(grown) < 10 * h:
            failures.append(f"beta 0: the tips grew only {min(grown):.3g} m (the test needs 10 mm)")
        if off > 0.5 * h:
            failures.append(f"beta 0: the path leaves the axis by {off:.3g} m (bound half a cell)")
        n = min(len(tips[0]), len(tips[1]))
        mirror = np.abs(tips[0]["x"][:n] + tips[1]["x"][:n]).max() if n else 0.0
        print(f"   0: tips mirrored within {mirror * 1e3:.3f} mm")
        if mirror > 0.5 * h:
            failures.append(f"beta 0: the tips are not mirror images ({mirror:.3g} m, bound half a cell)")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("first growth steps within 3 degrees of the maximum hoop stress direction")
