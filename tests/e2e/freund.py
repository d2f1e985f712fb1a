"""Freund's dynamic K_I(t) of a stationary semi-infinite crack whose faces are suddenly loaded by
a pressure p (Freund, Dynamic Fracture Mechanics, 1990, sec. 2.5; SPEC E18), plane strain:
    K_I(t) = 2 p sqrt(c_D t (1 - 2 nu) / pi) / (1 - nu),
and the check the e2e scripts share: every row of stress_intensity_NAME.csv from 1.5 to 2.6 us
(each domain) within 5 % of it, K_II within 1 % of K_I, the tip at x = 20 mm."""
import math
import sys

import numpy as np


def freund_k(t, p, E, nu, rho):
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    cD = math.sqrt((lam + 2 * mu) / rho)
    return 2 * p * np.sqrt(cD * t * (1 - 2 * nu) / math.pi) / (1 - nu)


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
    print("ok")
