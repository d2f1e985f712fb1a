#!/usr/bin/python3
"""Compare a TPV103-2D run (examples/tpv103_2d.toml, tpv103_2d_nested.toml) with the converged
reference tests/data/validation/tpv103-2d-converged (its README: uguca's algorithm at 25 m, and at
100 m with dt = 0.025 dx/c_s; rupture times checked at every step, not only at the 0.1 s dumps).

    scripts/tpv103_compare.py RUN_DIR [REF_DIR] [--grid 25m] [--until 9] [--stations 0,2.5,...]
                              [--check] [--tol-t 0.05] [--tol-t75 0.1] [--tol-slip 0.02]
                              [--tol-arrest 1.0]

RUN_DIR: a run's output (rupture_time_fault.csv, stations/faultstNNN.csv). REF_DIR defaults to
tests/data/validation/tpv103-2d-converged beside this script. Prints, per station (0, 2.5, 5, 7.5,
9, 12, 15, 18 km): our rupture time (slip rate of the slip path > 1 mm/s, linear between the nodes
around the station), the reference's (every step, rupture_time_GRID.txt), the difference; the
largest relative slip difference over the reference's dumps from 1 s after rupture to --until
(9 s: the periodic images come after; rows beyond 15 km are shown, not checked), our slip and the
reference's at --until; then the arrest position (the largest x >= 0 that ruptured; the
reference's from its rupture-time file) and whether the run lasted long enough to see it.
--check: exit 1 unless every rupture time at 0-18 km is within --tol-t of the reference's
(--tol-t75 at 7.5 km, where the early supershear transient dies and the converged settings differ
most), every slip at 0-15 km within --tol-slip, and, when the run reaches the reference's arrest
time + 0.75 s, the arrest within --tol-arrest km.
"""
import argparse
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_REF = os.path.join(HERE, "..", "tests", "data", "validation", "tpv103-2d-converged")
STATIONS = (0.0, 2.5, 5.0, 7.5, 9.0, 12.0, 15.0, 18.0)


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    head = rows[0]
    return {k: [float(r[i]) for r in rows[1:]] for i, k in enumerate(head)}


def read_columns(path):
    rows = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        rows.append([float(v) for v in line.split()])
    return rows


def interp(xs, ys, x):
    if x <= xs[0]:
        return ys[0]
    for i in range(1, len(xs)):
        if xs[i] >= x:
            f = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] > xs[i - 1] else 1.0
            return ys[i - 1] + f * (ys[i] - ys[i - 1])
    return ys[-1]


def run_rupture_time(rt, x):
    """Our rupture time at x (m), linear between the fault nodes around it; -1 if not ruptured."""
    xs, ts = rt["x"], rt["rupture_time"]
    for i in range(1, len(xs)):
        if xs[i] >= x:
            if ts[i - 1] >= 0 and ts[i] >= 0:
                f = (x - xs[i - 1]) / (xs[i] - xs[i - 1])
                return ts[i - 1] + f * (ts[i] - ts[i - 1])
            return -1.0
    return -1.0


def run_arrest(rt):
    """The largest x >= 0 (km) that ruptured, and the largest -x (km): the rupture's extent."""
    right = [x for x, t in zip(rt["x"], rt["rupture_time"]) if x >= 0 and t >= 0]
    left = [-x for x, t in zip(rt["x"], rt["rupture_time"]) if x <= 0 and t >= 0]
    return (max(right) / 1e3 if right else 0.0), (max(left) / 1e3 if left else 0.0)


def reference_rupture(ref, grid):
    rows = read_columns(os.path.join(ref, f"rupture_time_{grid}.txt"))
    times = {round(r[0] * 1000.0): r[1] for r in rows}
    ruptured = [r for r in rows if r[0] >= 0 and not math.isnan(r[1])]
    far = max(ruptured, key=lambda r: r[0])
    return times, far[0], far[1]


def compare(run, ref=DEFAULT_REF, grid="25m", until=9.0, stations=STATIONS):
    """Rows (km, ours, reference, difference, largest slip difference to `until`, our slip and
    the reference's at `until`), the arrest (ours km, its left mirror km, reference km and time),
    and our run's end time."""
    rt = read_csv(os.path.join(run, "rupture_time_fault.csv"))
    ref_times, ref_arrest, ref_arrest_t = reference_rupture(ref, grid)
    rows = []
    t_end = 0.0
    for km in stations:
        x = km * 1000.0
        t_r = run_rupture_time(rt, x)
        t_ref = ref_times[round(x)]
        diff = math.inf if t_r < 0 else t_r - t_ref
        worst, s_ours, s_ref = math.nan, math.nan, math.nan
        path = os.path.join(run, "stations", "faultst%03d.csv" % round(km * 10))
        if os.path.exists(path):
            ours = read_csv(path)
            t_end = max(t_end, ours["time"][-1])
            ref_rows = read_columns(os.path.join(ref, f"station_{grid}_xp{km:04.1f}km.txt"))
            tref = [r[0] for r in ref_rows]
            sref = [r[1] for r in ref_rows]
            worst = 0.0
            for t, s in zip(tref, sref):
                if t < max(t_r, t_ref) + 1.0 or t > until + 1e-9 or t > ours["time"][-1]:
                    continue
                worst = max(worst, abs(interp(ours["time"], ours["slip"], t) / s - 1.0))
            s_ours = interp(ours["time"], ours["slip"], until)
            s_ref = interp(tref, sref, until)
        rows.append((km, t_r, t_ref, diff, worst, s_ours, s_ref))
    right, left = run_arrest(rt)
    return rows, (right, left, ref_arrest, ref_arrest_t), t_end


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    ap.add_argument("ref", nargs="?", default=DEFAULT_REF)
    ap.add_argument("--grid", default="25m")
    ap.add_argument("--until", type=float, default=9.0)
    ap.add_argument("--stations", default=",".join(f"{s:g}" for s in STATIONS))
    ap.add_argument("--tol-t", type=float, default=0.05)
    ap.add_argument("--tol-t75", type=float, default=0.1)
    ap.add_argument("--tol-slip", type=float, default=0.02)
    ap.add_argument("--tol-arrest", type=float, default=1.0)
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    stations = tuple(float(s) for s in a.stations.split(","))
    rows, (right, left, ref_arrest, ref_arrest_t), t_end = compare(a.run, a.ref, a.grid, a.until, stations)
    ok = True
    print(f"| station (km) | rupture time (s) | reference {a.grid} (s) | difference (s) | "
          f"slip: largest difference to {a.until:g} s | slip at {a.until:g} s: ours / reference (m) |")
    print("|---|---|---|---|---|---|")
    for km, t_r, t_ref, diff, worst, s_ours, s_ref in rows:
        tol = a.tol_t75 if abs(km - 7.5) < 1e-9 else a.tol_t
        good = abs(diff) <= tol
        if km <= 15.0 + 1e-9 and not math.isnan(worst):
            good = good and worst <= a.tol_slip
        ok = ok and good
        print(f"| {km:.1f} | {t_r:.3f} | {t_ref:.3f} | {diff:+.3f} | {100 * worst:.2f} % | "
              f"{s_ours:.3f} / {s_ref:.3f} |" + ("" if good else " outside"))
    seen = t_end >= ref_arrest_t + 0.75
    print(f"arrest: ours {right:.2f} km (x < 0: {left:.2f} km) by {t_end:.2f} s; reference "
          f"{ref_arrest:.2f} km at {ref_arrest_t:.2f} s"
          + ("" if seen else " (the run ends before the reference's arrest + 0.75 s: not compared)"))
    if seen and abs(right - ref_arrest) > a.tol_arrest:
        ok = False
        print("arrest outside")
    if a.check and not ok:
        sys.exit(1)


if __name__ == "__main__":
    main()
