#!/usr/bin/env python3
"""Stations of examples/slip_weakening_1d.toml (docs/faults.md): the body station 500 m above the
fault moves with half the fault's slip rate one S-wave transit later (a plane S wave carries
v = V/2 away from each face), within 2 %; the fault station's traction is the dynamic strength
once the slip passes Dc; the rupture-time profile lists every node, ruptured in the first step.
Usage: check_stations.py RUN_DIR"""
import csv
import sys

import numpy as np

run = sys.argv[1]
f = np.loadtxt(f"{run}/stations/fault_centre.csv", delimiter=",", skiprows=1)
b = np.loadtxt(f"{run}/stations/above_500m.csv", delimiter=",", skiprows=1)
cs = 3464.0
y = b[0, 2]  # the particle's height
worst = 0.0
for t in (0.3, 0.35, 0.4, 0.45, 0.5, 0.54):
    vb = np.interp(t, b[:, 0], b[:, 3])
    vf = np.interp(t - y / cs, f[:, 0], f[:, 2])
    err = vb / (0.5 * vf) - 1.0
    worst = max(worst, abs(err))
    print(f"t = {t:.2f} s: body v = {vb:.4f} m/s, half the fault's slip rate {y / cs:.4f} s before "
          f"= {0.5 * vf:.4f} m/s ({100 * err:+.2f} %)")
assert worst < 0.02, f"body station off by {100 * worst:.2f} %"
late = f[f[:, 1] > 0.45]
tau_d = 0.525 * 120e6
assert len(late) > 0 and np.allclose(late[:, 4], tau_d, rtol=1e-3), late[:, 4]
print(f"shear traction past Dc: {late[:, 4].min():.5g} .. {late[:, 4].max():.5g} Pa (tau_d = {tau_d:.5g})")
rows = list(csv.DictReader(open(f"{run}/rupture_time_fault.csv")))
assert len(rows) == 5, len(rows)
for r in rows:
    assert 0.0 < float(r["rupture_time"]) < 2e-3, r
    assert abs(float(r["peak_slip_rate"]) / 4.0221 - 1.0) < 0.02, r
print("rupture_time_fault.csv:", [float(r["rupture_time"]) for r in rows])
# Columns by name: the fault file's slip_rate is friction's (the slip path's rate), jump_rate the
# tangential jump's (with the stick spring's elastic part); the body file adds ux, uy.
fh = open(f"{run}/stations/fault_centre.csv").readline().strip().split(",")
bh = open(f"{run}/stations/above_500m.csv").readline().strip().split(",")
assert fh == ["time", "slip", "slip_rate", "opening", "shear_traction", "normal_traction", "jump_rate"], fh
assert bh == ["time", "x", "y", "vx", "vy", "ux", "uy"], bh
# Sliding at a steady rate (after the weakening), the elastic jump no longer changes: the two rates
# agree; friction's rate is never negative here (the slip grows one way).
steady = f[f[:, 0] > 0.3]
rel = np.max(np.abs(steady[:, 6] / steady[:, 2] - 1.0))
assert rel < 0.01, rel
assert f[:, 2].min() >= 0.0
print(f"steady sliding: jump_rate / slip_rate - 1 within {rel:.2e}")
# The body station's displacement is its position less the first (t = 0) sample's (to the
# printing's 10 digits of x), and the time integral of its velocity (trapezoid rule over the
# samples) within 0.5 % of its final value.
assert np.allclose(b[:, 5], b[:, 1] - b[0, 1], rtol=0, atol=1e-9 * np.abs(b[:, 1]).max())
ux_int = np.concatenate([[0.0], np.cumsum(0.5 * np.diff(b[:, 0]) * (b[1:, 3] + b[:-1, 3]))])
err = np.max(np.abs(b[:, 5] - ux_int)) / abs(b[-1, 5])
assert err < 5e-3, err
print(f"body ux: final {b[-1, 5]:.6g} m, integral of vx within {100 * err:.3f} % of it")
