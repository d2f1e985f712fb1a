#!/usr/bin/env python3
"""What the slow crack does before the regime threshold (issue 14): one row per run of one or
more `rupture sweep` directories over boundary.impact.velocity.

Usage: /usr/bin/python3 scripts/threshold.py SWEEP_DIR...

Per run: the finest cell h, V, initiation, the E11 speed's mean and its swing (max - min) over
the sub-Rayleigh running phase (from 3 us after initiation to the first time above c_S, or to the
end), the softening (cohesive) zone over the same phase in mm and in cells of h, the first time
the E11 speed passes c_R and c_S, and the tip's x then. A crack that jumps to intersonic
does so from this phase; the swing is the noise that can carry a tip near c_R past it.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import rupture  # noqa: E402  (the package's readers: one reader per file, python/rupture)


def row(run_dir):
    opened = rupture.open_run(run_dir)
    run = opened.record
    speeds = next(iter(run["wave_speeds"].values()))
    c_r, c_s = speeds["rayleigh"], speeds["shear"]
    h = run["input"]["grid"]["cell_size"]
    v_imp = run["input"]["boundary"]["impact"]["velocity"]
    tips = opened.crack_tip()
    t, x, v, zone = tips["time"], tips["tip_x"], tips["speed"], tips["cohesive_zone_length"]
    t0 = run["crack"]["initiation_time"]
    if t0 is None or t0 < 0:  # null (before: -1): never initiated
        return f"| {1e6 * h:g} | {v_imp:g} | - | | | | | | |"
    finite = np.isfinite(v)

    def first(level):
        i = np.flatnonzero(finite & (t > t0) & (v > level))
        return (t[i[0]], x[i[0]]) if i.size else (None, None)

    t_r, x_r = first(c_r)
    t_s, x_s = first(c_s)
    phase = finite & (t >= t0 + 3e-6) & (t < (t_s if t_s is not None else np.inf))
    mean = v[phase].mean() if phase.any() else float("nan")
    swing = v[phase].max() - v[phase].min() if phase.any() else float("nan")
    z = np.median(zone[phase]) if phase.any() else float("nan")

    def when(tt, xx):
        return f"{1e6 * tt:.2f} ({1e3 * xx:.1f} mm)" if tt is not None else "-"

    if not phase.any():  # no sub-Rayleigh phase 3 us after initiation
        return f"| {1e6 * h:g} | {v_imp:g} | {1e6 * t0:.2f} | - | - | - | {when(t_r, x_r)} | {when(t_s, x_s)} |"
    return (f"| {1e6 * h:g} | {v_imp:g} | {1e6 * t0:.2f} | {mean:.0f} ({mean / c_r:.3f} c_R) | {swing:.0f} "
            f"| {1e3 * z:.3f} ({z / h:.1f}) | {when(t_r, x_r)} | {when(t_s, x_s)} |")


def main(dirs):
    print("| h (um) | V (m/s) | initiation (us) | mean speed, sub-Rayleigh phase (m/s) | swing (m/s) "
          "| softening zone (mm, cells) | first > c_R (us, tip x) | first > c_S (us, tip x) |")
    print("|---|---|---|---|---|---|---|---|")
    runs = []
    for d in dirs:
        sweep = rupture.open_run(d)
        for k in range(len(sweep)):
            r = sweep.row(k)
            if r["status"] == "completed":
                runs.append((float(r["boundary.impact.velocity"]), f"{d}/{r['run']}"))
    for _, run_dir in sorted(runs):
        print(row(run_dir))


if __name__ == "__main__":
    main(sys.argv[1:])
