#!/usr/bin/env python3
"""Rupture-front speed along a fault from DIR/rupture_time_NAME.csv (the SCEC rupture time,
slip rate above 1 mm/s): the local speed ds/dt over windows of `window` metres on each side of
the nucleation point, and the supershear transition distance, the first distance from the
hypocentre past which the front runs faster than c_S over a whole window.
The nucleation patch breaks at once: distances within `skip` metres (default 2000, the TPV205
patch's half-length 1500 m and one window half) of the hypocentre are left out.
The run's own summary of the front (run.json cracks[].front, cohesive/rupture_front.hpp) uses
5-cell windows from the overstressed patch's edge and places the transition where the front
turns supershear for good; this script's transition is the first window past c_S.
Usage: front_speed.py RUN_DIR [interface name] [c_S m/s] [window m] [skip m] [c_P m/s]"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import rupture  # noqa: E402  (the package's readers: one reader per file, python/rupture)

run = sys.argv[1]
name = sys.argv[2] if len(sys.argv) > 2 else "fault"
cs = float(sys.argv[3]) if len(sys.argv) > 3 else 3464.0
window = float(sys.argv[4]) if len(sys.argv) > 4 else 1000.0
skip = float(sys.argv[5]) if len(sys.argv) > 5 else 2000.0
cp = float(sys.argv[6]) if len(sys.argv) > 6 else 6000.0
profile = rupture.open_run(run).rupture_time(name)
x, t = profile["x"], profile["rupture_time"]
ok = t >= 0
# The hypocentre: the middle of the nodes that ruptured first (a nucleation patch breaks at once).
first = ok & (t <= t[ok].min() + 1e-12)
x0 = 0.5 * (x[first].min() + x[first].max())
for side, sign in (("east", 1.0), ("west", -1.0)):
    d = sign * (x - x0)
    sel = ok & (d >= 0)
    dd, tt = d[sel], t[sel]
    order = np.argsort(dd)
    dd, tt = dd[order], tt[order]
    transition = None
    print(f"{side}: distance (km), local front speed (m/s)")
    for start in np.arange(skip, dd.max() - window, window / 2):
        m = (dd >= start) & (dd <= start + window)
        if m.sum() < 3:
            continue
        v = np.polyfit(tt[m], dd[m], 1)[0]
        print(f"  {start / 1e3:6.2f} - {(start + window) / 1e3:6.2f}: {v:7.0f}")
        # Faster than c_P is no propagating front (what the nucleation patch breaks at once).
        if transition is None and cs < v < 1.05 * cp:
            transition = start
    print(f"{side}: supershear_transition_distance_m={transition if transition is not None else -1}")
