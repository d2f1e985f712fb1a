#!/usr/bin/python3
"""An independent reference for Freund's running crack (docs/fracture.md, "A running tip"): the
same problem as tests/e2e/check_running_tip.py solved by finite differences, with no rupture
code. A semi-infinite crack on y = 0 in a plane-strain solid (Homalite: E 5.2 GPa, nu 0.34,
rho 1246 kg/m^3) has its faces suddenly loaded by sigma0 = 5 MPa at t = 0 wherever they are free,
and its tip runs on at v from t = 0 (the prestressed plate's problem by superposition). The
upper half y > 0 is solved (mode I symmetry) with Virieux's staggered velocity-stress scheme
(2nd order; v_y and the normal stresses at cell centres along x): on y = 0, sigma_xy = 0; behind
the tip the face carries -sigma0 (half-cell update of v_y), ahead of it v_y = 0, and a v_y point
is released when the tip's position v t passes it. The domain [-10, 35] x [0, 15] mm puts every
edge out of the tip's reach up to 6 us. K_I is read from the opening behind the tip, u_y =
c(v) K sqrt(r) (the running field's, fracture/running_tip_field.hpp; c(0) = 2 (1 - nu) /
(mu sqrt(2 pi))), extrapolated linearly in r to the tip from 1-12 cells, every step, and averaged
over 3-6 us (the tip jumps node by node, so single readings swing); then divided by Freund's
K_I(t, 0) = 2 sigma0 sqrt(c_D t (1 - 2 nu)/pi)/(1 - nu) and by the same reading at v = 0, which
is 1.094 at 0.05 and 0.025 mm alike (the extrapolation's own bias, fixed in cells).
Usage: freund_running_fd.py [CELL_MM] [V/c_R ...]   (defaults 0.05 and 0 0.15 0.3 0.45 0.6 0.75;
about 45 s a speed at 0.05 mm, 4 min at 0.025 mm, numpy only). Prints, per speed, the reading
over Freund's K_I(t, 0) and the universal function k(v) of tests/e2e/freund.py beside it."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "e2e"))
from freund import universal_k, wave_speeds  # noqa: E402

E, NU, RHO, S0 = 5.2e9, 0.34, 1246.0, 5e6
LAM, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
M = LAM + 2 * MU
CD, CS, CR = wave_speeds(E, NU, RHO)


def opening_coefficient(v):
    """u_y on the upper face = c K sqrt(r) for a tip running at v (Freund's field at theta = pi)."""
    if v < 1e-3 * CS:
        return 2 * (1 - NU) / (MU * math.sqrt(2 * math.pi))
    ad, a_s = math.sqrt(1 - v * v / CD**2), math.sqrt(1 - v * v / CS**2)
    D = 4 * ad * a_s - (1 + a_s * a_s) ** 2
    return 2 * ad * (1 - a_s * a_s) / (math.sqrt(2 * math.pi) * MU * D)


def run(v, h, x0=-0.01, x1=0.035, H=0.015, tip0=0.02, end=6e-6, cfl=0.4):
    """Mean over 3-6 us of K_I / K_I(t, 0) read from the opening behind the tip."""
    nx, ny = int(round((x1 - x0) / h)), int(round(H / h))
    xc = x0 + (np.arange(nx) + 0.5) * h
    vx, vy, uy = np.zeros((nx + 1, ny)), np.zeros((nx, ny + 1)), np.zeros(nx)
    sxx, syy, sxy = np.zeros((nx, ny)), np.zeros((nx, ny)), np.zeros((nx + 1, ny + 1))
    n = int(math.ceil(end / (cfl * h / CD)))
    dt = end / n
    coef = opening_coefficient(v)
    readings = []
    for k in range(n):
        vx[1:-1, :] += dt / RHO * ((sxx[1:, :] - sxx[:-1, :]) / h + (sxy[1:-1, 1:] - sxy[1:-1, :-1]) / h)
        vy[:, 1:-1] += dt / RHO * ((sxy[1:, 1:-1] - sxy[:-1, 1:-1]) / h + (syy[:, 1:] - syy[:, :-1]) / h)
        face = xc < tip0 + v * (k + 0.5) * dt
        vy[face, 0] += dt / RHO * 2.0 * (syy[face, 0] + S0) / h  # the face's traction -S0, half a cell
        vy[~face, 0] = 0.0
        uy += dt * vy[:, 0]
        dvx, dvy = (vx[1:, :] - vx[:-1, :]) / h, (vy[:, 1:] - vy[:, :-1]) / h
        sxx += dt * (M * dvx + LAM * dvy)
        syy += dt * (LAM * dvx + M * dvy)
        sxy[1:-1, 1:-1] += dt * MU * ((vx[1:-1, 1:] - vx[1:-1, :-1]) / h + (vy[1:, 1:-1] - vy[:-1, 1:-1]) / h)
        t = (k + 1) * dt
        if t < 3e-6:
            continue
        tip = xc[np.nonzero(face)[0].max()] + 0.5 * h  # between the last free and the first held point
        r = tip - xc
        sel = (r > h) & (r < 12 * h)
        K = np.polyfit(r[sel], uy[sel] / (coef * np.sqrt(r[sel])), 1)[1]
        readings.append(K / (2 * S0 * math.sqrt(CD * t * (1 - 2 * NU) / math.pi) / (1 - NU)))
    return float(np.mean(readings))


if __name__ == "__main__":
    h = float(sys.argv[1]) * 1e-3 if len(sys.argv) > 1 else 0.05e-3
    fracs = [float(a) for a in sys.argv[2:]] or [0.0, 0.15, 0.3, 0.45, 0.6, 0.75]
    still = run(0.0, h)
    print(f"cell {h * 1e3:.3g} mm: at rest K_I / K_I(t, 0) = {still:.4f} (the extrapolation's bias, divided out below)")
    for f in fracs:
        m = still if f == 0.0 else run(f * CR, h)
        print(f"v = {f:.2f} c_R: K_I / K_I(t, 0) = {m / still:.4f}   k(v) = {universal_k(f * CR, E, NU, RHO):.4f}",
              flush=True)
