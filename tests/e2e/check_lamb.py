#!/usr/bin/python3
"""Lamb's problem (examples/lamb_2d.toml) at two cell sizes against the exact surface
displacements (tests/data/validation/lamb-2d-sem2dpack): the physics a wrong source, free
surface or station would miss, and the convergence.
  - the body stations' files carry ux, uy (m);
  - the first motion (|u_z| above 1e-3 of its peak, the P wave) arrives at both receivers within
    5 ms of the exact time (R1 0.317 s, R2 0.473 s) with the exact sign;
  - the Rayleigh pulse's delay (the lag of the cross-correlation with the exact trace; the
    grid's dispersion makes it slow) falls at least as fast as h^1.5 from the coarse to the fine
    run (second order measured: 25.5, 18, 12, 4.5 ms at 12.5, 10, 8, 5 m on R2 u_z), and is
    below 4 % of the pulse's travel time offset / c_R on the fine run;
  - the peak-normalised misfit (scripts/lamb_compare.py, SEM2DPACK's measure) falls at both
    receivers, both components.
Usage: check_lamb.py COARSE_RUN H_COARSE FINE_RUN H_FINE"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import lamb_compare  # noqa: E402

coarse, h_coarse, fine, h_fine = sys.argv[1], float(sys.argv[2]), sys.argv[3], float(sys.argv[4])
ref = np.loadtxt(lamb_compare.DEFAULT_REF)
t = ref[:, 0]
c_r = 0.9194 * 1847.5  # Rayleigh speed for nu = 0.25 (the reference's README)
force = 1e9            # the example's |F|, N/m; the reference is for 1 N/m
receivers = {"R1": (700.0, 1, 2), "R2": (1200.0, 3, 4)}


def trace(run, name, key):
    head = open(f"{run}/stations/{name}.csv").readline().strip().split(",")
    assert head == ["time", "x", "y", "vx", "vy", "ux", "uy"], head
    s = np.loadtxt(f"{run}/stations/{name}.csv", delimiter=",", skiprows=1)
    return np.interp(t, s[:, 0], s[:, head.index(key)]) / force


def lag(u, r):
    """Delay of u behind r, s (the lag maximising their cross-correlation, within 50 ms)."""
    lags = np.arange(-100, 101)
    return 0.5e-3 * lags[int(np.argmax([np.dot(np.roll(r, k), u) for k in lags]))]


misfit = {run: {(n, c): m for n, c, m, _, _ in lamb_compare.compare(run)} for run in (coarse, fine)}
for name, (offset, cx, cz) in receivers.items():
    r = ref[:, cz]
    first = t[np.argmax(np.abs(r) > 1e-3 * np.abs(r).max())]
    u = trace(fine, name, "uy")
    ours = t[np.argmax(np.abs(u) > 1e-3 * np.abs(u).max())]
    sign_ref = np.sign(r[np.argmax(np.abs(r) > 1e-3 * np.abs(r).max())])
    sign = np.sign(u[np.argmax(np.abs(u) > 1e-3 * np.abs(u).max())])
    print(f"{name}: first motion {ours:.4f} s (exact {first:.4f} s), sign {sign:+.0f} (exact {sign_ref:+.0f})")
    assert abs(ours - first) <= 5e-3 and sign == sign_ref
    for comp, key, col in (("ux", "ux", cx), ("uz", "uy", cz)):
        lc, lf = lag(trace(coarse, name, key), ref[:, col]), lag(trace(fine, name, key), ref[:, col])
        bound = (h_fine / h_coarse) ** 1.5
        mc, mf = misfit[coarse][(name, comp)], misfit[fine][(name, comp)]
        print(f"{name} {comp}: Rayleigh delay {1e3 * lc:.1f} ms at {h_coarse:g} m -> {1e3 * lf:.1f} ms at "
              f"{h_fine:g} m (ratio {lf / lc:.2f}, at most {bound:.2f}; {100 * lf / (offset / c_r):.2f} % "
              f"of the travel time); misfit {100 * mc:.1f} % -> {100 * mf:.1f} %")
        assert lc > 0 and lf / lc <= bound, (lc, lf)
        assert lf < 0.04 * offset / c_r
        assert mf < mc
print("lamb: ok")
