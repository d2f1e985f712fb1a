#!/usr/bin/python3
"""K of a running tip (docs/fracture.md, "A running tip"): Freund's crack that runs at a constant
speed v from the moment its faces are loaded. A plate under a uniform initial stress
sigma_yy = sigma0 holds an edge crack from x = 0 to 20 mm drawn inside it (law = "contact"),
cut at t = 0, whose tip runs straight on at v from t = 0 (growth = "prescribed", running_tip =
true). By superposition its faces carry a suddenly applied pressure sigma0 wherever they are
free; a crack tip that had stood anywhere on the line would have K_I(t, 0) =
2 sigma0 sqrt(c_D t (1 - 2 nu)/pi)/(1 - nu) (the loading reaches every point of the line at
t = 0), so by Freund's result for a tip in arbitrary motion (Dynamic Fracture Mechanics, 1990,
ch. 7) K_I(t, v) = k(v) K_I(t, 0), k the universal function (freund.universal_k, exact through
the Wiener-Hopf factor of the Rayleigh function; scripts/freund_running_fd.py solves the same
problem by finite differences, independently of rupture, and finds it: docs/fracture.md). Until
the release waves from the plate's free top and bottom edges (20 mm away) reach the crack line
(7.9 us).
Checked (the mean of K_I / K_I(t, 0) over 3-7.5 us and the three J domains, read with the
running tip's fields): within 5 % of 1 at v = 0 and of k(v) at 0.3 and 0.6 c_R, falling with v;
the speed column is the prescribed speed; the factorization behind k is checked against the
Rayleigh function.
Usage: check_running_tip.py RUPTURE WORK_DIR"""
import math
import os
import subprocess
import sys

import numpy as np

from freund import freund_k, prestressed_edge_crack, universal_k, wave_speeds

rupture, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
E, nu, rho, s0 = 5.2e9, 0.34, 1246.0, 5e6
cD, cS, cR = wave_speeds(E, nu, rho)

# The reference's own check: S_+(z) S_-(z) = R(z) / (2 (b^2 - a^2)(c^2 - z^2)) at real z > b.
a, b, c = 1 / cD, 1 / cS, 1 / cR
n = 200000
e = a + (np.arange(n) + 0.5) * (b - a) / n
theta = np.arctan2(4 * e * e * np.sqrt((e * e - a * a) * (b * b - e * e)), (b * b - 2 * e * e) ** 2)
for z in (1.5 * b, 3 * b):
    product = math.exp(-np.sum(theta * (1 / (e + z) + 1 / (e - z))) * (b - a) / n / math.pi)
    R = (b * b - 2 * z * z) ** 2 - 4 * z * z * math.sqrt(z * z - a * a) * math.sqrt(z * z - b * b)
    assert abs(product / (R / (2 * (b * b - a * a) * (c * c - z * z))) - 1) < 1e-6, "Wiener-Hopf factors"


def case(v):
    growth = (f'growth = "prescribed"\ngrowth_speed = {v!r}\ngrowth_direction = "straight"\nrunning_tip = true\n'
              if v > 0 else "stress_intensity = true\n")
    return prestressed_edge_crack(f"Freund's running crack: edge crack cut into a prestressed plate, its tip run at "
                                  f"{v:.1f} m/s", E, nu, rho, s0, 0.05, 0.02, growth, 7.5e-6, 0.05e-6)


def mean_ratio(v):
    name = f"v{int(round(v))}"
    path = os.path.join(work, name + ".toml")
    open(path, "w").write(case(v))
    out = os.path.join(work, name)
    subprocess.run([rupture, "run", path, "-o", out, "--overwrite", "--quiet"], check=True, stdout=subprocess.DEVNULL)
    d = np.genfromtxt(os.path.join(out, "stress_intensity_crack.csv"), delimiter=",", names=True)
    rows = d[(d["time"] >= 3e-6) & (d["time"] <= 7.5e-6)]
    r = rows["K_I"] / freund_k(rows["time"], s0, E, nu, rho)
    assert np.all(np.abs(rows["speed"] - v) <= 1e-5 * max(v, 1.0)), "the speed column is the tip's prescribed speed"
    k = universal_k(v, E, nu, rho)
    print(f"v = {v:7.1f} m/s ({v / cR:.2f} c_R): K_I / K_I(t,0) mean {r.mean():.4f} (min {r.min():.4f}, "
          f"max {r.max():.4f}, {len(r)} rows) against k(v) = {k:.4f}: {r.mean() / k:.4f}; tip at "
          f"{rows['x'][-1] * 1e3:.2f} mm (due {20 + v * 7.5e-3:.2f})")
    return r.mean(), k


failed = False
means = []
for frac in (0.0, 0.3, 0.6):
    m, k = mean_ratio(frac * cR)
    means.append(m)
    if abs(m / k - 1) > 0.05:
        print(f"FAILED: at {frac} c_R K_I is {m / k:.4f} of Freund's k(v) K_I(t, 0)")
        failed = True
if not means[0] > means[1] > means[2]:
    print("FAILED: K_I of the running tip does not fall with its speed")
    failed = True
print("FAILED" if failed else "ok")
sys.exit(1 if failed else 0)
