#!/usr/bin/env python3
"""How far consecutive resolutions of the bimaterial fault lie apart (docs/faults.md,
"Normal-stress regularization"), for each form the study ran (OUT/slip, OUT/none): over the
stations at 0, +-4.5, +-7.5, +-12 km, the largest difference in rupture time (s), in final slip
and in peak slip rate (both relative to the finer run's), and the finer run's final slip at the
hypocentre (m). Usage: bimaterial_convergence.py OUT_DIR CELL_SIZES..."""
import os
import sys

import numpy as np

STATIONS = ["st_m12", "st_m7p5", "st_m4p5", "st0", "st_p4p5", "st_p7p5", "st_p12"]


def record(run, name):
    d = np.loadtxt(f"{run}/stations/{name}.csv", delimiter=",", skiprows=1)
    return d[:, 0], d[:, 1], d[:, 2]


def rupture_time(t, v):
    hit = np.nonzero(np.abs(v) > 1e-3)[0]
    return t[hit[0]] if len(hit) else np.inf


out, sizes = sys.argv[1], sys.argv[2:]
print("| form | cells | rupture time (s) | final slip | peak slip rate | hypocentre slip (m) |")
print("|---|---|---|---|---|---|")
for form in ("slip", "none"):
    if not os.path.isdir(f"{out}/{form}"):
        continue
    for coarse, fine in zip(sizes, sizes[1:]):
        dt_r = ds = dp = 0.0
        for name in STATIONS:
            tc, sc, vc = record(f"{out}/{form}/h{coarse}", name)
            tf, sf, vf = record(f"{out}/{form}/h{fine}", name)
            dt_r = max(dt_r, abs(rupture_time(tc, vc) - rupture_time(tf, vf)))
            ds = max(ds, abs(sc[-1] - sf[-1]) / max(abs(sf[-1]), 1e-12))
            pf = np.abs(vf).max()
            dp = max(dp, abs(np.abs(vc).max() - pf) / pf)
        print(f"| {form} | {coarse} -> {fine} m | {dt_r:.3f} | {100 * ds:.2f} % | {100 * dp:.1f} % | "
              f"{record(f'{out}/{form}/h{fine}', 'st0')[1][-1]:.3f} |")
