"""Freund's dynamic K_I(t) of a stationary semi-infinite crack whose faces are suddenly loaded by
a pressure p (Freund, Dynamic Fracture Mechanics, 1990, sec. 2.5; theory E18), plane strain:
    K_I(t) = 2 p sqrt(c_D t (1 - 2 nu) / pi) / (1 - nu),
and the check the e2e scripts share: every row of stress_intensity_NAME.csv from 1.5 to 2.6 us
(each domain) within 5 % of it, K_II within 1 % of K_I, J within 10.25 % (1.05^2 - 1) of
K_I^2 / E', the tip at x = 20 mm."""
import math
import sys

import numpy as np


def freund_k(t, p, E, nu, rho):
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    cD = math.sqrt((lam + 2 * mu) / rho)
    return 2 * p * np.sqrt(cD * t * (1 - 2 * nu) / math.pi) / (1 - nu)


def wave_speeds(E, nu, rho):
    """c_D, c_S and c_R of the plane-strain solid (m/s)."""
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    cD, cS = math.sqrt((lam + 2 * mu) / rho), math.sqrt(mu / rho)
    lo, hi = 0.5 * cS, cS
    for _ in range(200):  # Rayleigh's function 4 a_d a_s - (1 + a_s^2)^2 changes sign at c_R
        v = 0.5 * (lo + hi)
        ad, a_s = math.sqrt(1 - v * v / cD**2), math.sqrt(1 - v * v / cS**2)
        if 4 * ad * a_s - (1 + a_s * a_s) ** 2 > 0:
            lo = v
        else:
            hi = v
    return cD, cS, 0.5 * (lo + hi)


def universal_k(v, E, nu, rho, n=200000):
    """Freund's universal function of a mode-I tip's speed (Dynamic Fracture Mechanics, 1990,
    sec. 5.3 and 7.4; plane strain): K_I(t, v) = k(v) K_I*(t), K_I* the stationary tip's under the
    same loading, with
        k(v) = (1 - v/c_R) S_-(1/v) / sqrt(1 - v/c_D),
        S_-(z) = exp{-(1/pi) int_a^b atan[4 e^2 sqrt((e^2 - a^2)(b^2 - e^2)) / (b^2 - 2 e^2)^2] de / (e - z)},
    a = 1/c_D, b = 1/c_S: the minus factor of the Rayleigh function's Wiener-Hopf split
    R(z) = 2 (b^2 - a^2)(1/c_R^2 - z^2) S_+(z) S_-(z) (midpoint rule, n points; S_+ S_- against R
    is checked in tests/e2e/check_running_tip.py). k(0) = 1, k(c_R) = 0."""
    cD, cS, cR = wave_speeds(E, nu, rho)
    if v <= 0.0:
        return 1.0
    a, b = 1 / cD, 1 / cS
    e = a + (np.arange(n) + 0.5) * (b - a) / n
    theta = np.arctan2(4 * e * e * np.sqrt((e * e - a * a) * (b * b - e * e)), (b * b - 2 * e * e) ** 2)
    s_minus = math.exp(-np.sum(theta / (e - 1 / v)) * (b - a) / n / math.pi)
    return (1 - v / cR) * s_minus / math.sqrt(1 - v / cD)


def prestressed_edge_crack(title, E, nu, rho, s0, width, half_height, crack_keys, end, sample):
    """The TOML of an edge crack (x = 0 to 20 mm on y = 0, law = "contact") drawn inside a Homalite
    plate [0, width] x [-half_height, half_height] (m) under sigma_yy = s0, so its faces are
    released at t = 0 (plane strain, 0.25 mm, 2 particles per cell); crack_keys: the crack's
    other keys (stress_intensity, growth, ...), one per line."""
    return f"""title = "{title}"
[model]
plane = "strain"
[materials.homalite]
youngs_modulus = {E!r}
poisson_ratio = {nu!r}
density = {rho!r}
[grid]
min = [0.0, {-half_height!r}]
max = [{width!r}, {half_height!r}]
cell_size = 0.25e-3
particles_per_cell = 2
[bodies.plate]
material = "homalite"
min = [0.0, {-half_height!r}]
max = [{width!r}, {half_height!r}]
stress = [0.0, {s0!r}, 0.0]
[interface.crack]
body = "plate"
points = [[0.0, 0.0], [0.02, 0.0]]
segments = 80
law = "contact"
{crack_keys}[time]
end = {end!r}
[output]
history_interval = {end / 25!r}
crack_sample_interval = {sample!r}
"""


def check_against_freund(d, p, E, nu, rho, least_rows, label):
    """Exits 1 (after saying why) unless the rows of `d` follow Freund's K_I(t)."""
    rows = d[(d["time"] >= 1.5e-6) & (d["time"] <= 2.6e-6)]
    assert len(rows) >= least_rows, f"{len(rows)} rows between 1.5 and 2.6 us"
    assert np.all(np.abs(rows["x"] - 0.02) < 1e-9), "the tip is the crack's (x = 20 mm)"
    ratio = rows["K_I"] / freund_k(rows["time"], p, E, nu, rho)
    print(f"{label}K_I / Freund from 1.5 to 2.6 us: {ratio.min():.4f} .. {ratio.max():.4f} over "
          f"{len(rows)} rows; |K_II / K_I| at most {np.max(np.abs(rows['K_II'] / rows['K_I'])):.2e}")
    if np.any(np.abs(ratio - 1) > 0.05):
        print("FAILED: K_I off Freund's by more than 5 %")
        sys.exit(1)
    if np.any(np.abs(rows["K_II"]) > 0.01 * np.abs(rows["K_I"])):
        print("FAILED: K_II in a mode I problem")
        sys.exit(1)
    # J of a stationary tip is K_I^2 / E' (plane strain): within K's 5 %, squared.
    j = rows["J"] / (freund_k(rows["time"], p, E, nu, rho) ** 2 * (1 - nu * nu) / E)
    print(f"{label}J / (K_Freund^2 / E') from 1.5 to 2.6 us: {j.min():.4f} .. {j.max():.4f}")
    if np.any(np.abs(j - 1) > 1.05**2 - 1):
        print("FAILED: J off K_Freund^2 / E' by more than 10.25 %")
        sys.exit(1)
    print("ok")
