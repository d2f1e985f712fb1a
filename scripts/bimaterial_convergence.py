#!/usr/bin/env python3
"""How far consecutive resolutions of the bimaterial fault lie apart (docs/faults.md,
"Normal-stress regularization"), for each form the study ran (OUT/slip, OUT/none): over the
stations at 0, +-4.5, +-7.5, +-12 km, the largest difference in rupture time (s), in final slip
and in peak slip rate (both relative to the finer run's), and the finer run's final slip at the
hypocentre (m). With --scales L...: for each L and cell size, how far the run at that L
(OUT/L<L>/h<cell>) lies from the example's L = 0.4 m (OUT/slip/h<cell>), the same measures.
Usage: bimaterial_convergence.py OUT_DIR CELL_SIZES... [--scales L...]"""
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


args = sys.argv[1:]
scales = args[args.index("--scales") + 1:] if "--scales" in args else []
args = args[:args.index("--scales")] if "--scales" in args else args
out, sizes = args[0], args[1:]


def apart(a, b):
    """Largest differences of run a from run b over the stations: rupture time (s), final slip
    and peak slip rate (relative to b's)."""
    dt_r = ds = dp = 0.0
    for name in STATIONS:
        tc, sc, vc = record(a, name)
        tf, sf, vf = record(b, name)
        dt_r = max(dt_r, abs(rupture_time(tc, vc) - rupture_time(tf, vf)))
        ds = max(ds, abs(sc[-1] - sf[-1]) / max(abs(sf[-1]), 1e-12))
        pf = np.abs(vf).max()
        dp = max(dp, abs(np.abs(vc).max() - pf) / pf)
    return dt_r, ds, dp


print("| form | cells | rupture time (s) | final slip | peak slip rate | hypocentre slip (m) |")
print("|---|---|---|---|---|---|")
for form in ("slip", "none"):
    if not os.path.isdir(f"{out}/{form}"):
        continue
    for coarse, fine in zip(sizes, sizes[1:]):
        dt_r, ds, dp = apart(f"{out}/{form}/h{coarse}", f"{out}/{form}/h{fine}")
        print(f"| {form} | {coarse} -> {fine} m | {dt_r:.3f} | {100 * ds:.2f} % | {100 * dp:.1f} % | "
              f"{record(f'{out}/{form}/h{fine}', 'st0')[1][-1]:.3f} |")
if scales:
    print()
    print("| L (m) | cells | rupture time (s) | final slip | peak slip rate | hypocentre slip (m) |")
    print("|---|---|---|---|---|---|")
    for L in scales:
        for h in sizes:
            dt_r, ds, dp = apart(f"{out}/L{L}/h{h}", f"{out}/slip/h{h}")
            print(f"| {L} vs 0.4 | {h} m | {dt_r:.3f} | {100 * ds:.2f} % | {100 * dp:.1f} % | "
                  f"{record(f'{out}/L{L}/h{h}', 'st0')[1][-1]:.3f} |")
