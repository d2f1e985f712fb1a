#!/usr/bin/python3
"""Compare a Lamb's-problem run (examples/lamb_2d.toml) with the exact surface displacements of
../shared/validation/lamb-2d-sem2dpack (copied to tests/data/validation/lamb-2d-sem2dpack; its
README gives the source, set-up and columns).

    scripts/lamb_compare.py RUN_DIR [--ref FILE] [--force 1e9] [--check TOL]

Reads RUN_DIR/stations/R1.csv and R2.csv (columns ux, uy, m), divides them by the force's
magnitude (N/m: the reference is for a unit line force; the problem is linear), interpolates
them linearly to the reference's samples (0.5 ms, 0 to 1.5 s) and prints, per receiver and
component, the misfit as SEM2DPACK's test defines it: the largest |u - u_ref| over the record,
divided by the largest |u_ref| (peak-normalised), and the peaks' times and values.
--check TOL: exit 1 unless every misfit is at most TOL (a fraction, e.g. 0.02).
"""
import argparse
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_REF = os.path.join(HERE, "..", "tests", "data", "validation", "lamb-2d-sem2dpack",
                           "lamb_analytic_EX2DDIR.txt")


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return {k: [float(r[i]) for r in rows[1:]] for i, k in enumerate(rows[0])}


def read_reference(path):
    cols = [[] for _ in range(5)]
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        for c, v in zip(cols, line.split()):
            c.append(float(v))
    t, ux1, uz1, ux2, uz2 = cols
    return t, {"R1": (ux1, uz1), "R2": (ux2, uz2)}


def resample(ts, vs, grid):
    """Linear interpolation of (ts, vs) at the increasing times `grid` (held past the ends)."""
    out, i = [], 0
    for t in grid:
        while i + 1 < len(ts) and ts[i + 1] < t:
            i += 1
        if t <= ts[0]:
            out.append(vs[0])
        elif i + 1 >= len(ts):
            out.append(vs[-1])
        else:
            f = (t - ts[i]) / (ts[i + 1] - ts[i])
            out.append(vs[i] + f * (vs[i + 1] - vs[i]))
    return out


def delay(ours, u_ref, dt, window=0.05):
    """The lag (s) that maximises the cross-correlation of ours with u_ref (equal samples dt):
    > 0 when ours arrives late."""
    n = int(round(window / dt))
    best, best_k = None, 0
    for k in range(-n, n + 1):
        c = sum(ours[i + k] * u_ref[i] for i in range(max(0, -k), min(len(u_ref), len(ours) - k)))
        if best is None or c > best:
            best, best_k = c, k
    return best_k * dt


def compare(run, ref=DEFAULT_REF, force=1e9):
    """Rows (receiver, component, misfit, (t, u) peak of ours, (t, u) peak of the reference)."""
    t_ref, refs = read_reference(ref)
    rows = []
    for name in ("R1", "R2"):
        s = read_csv(os.path.join(run, "stations", name + ".csv"))
        for comp, key, u_ref in (("ux", "ux", refs[name][0]), ("uz", "uy", refs[name][1])):
            t_end = min(s["time"][-1], t_ref[-1])
            grid = [t for t in t_ref if t <= t_end + 1e-12]
            ours = resample(s["time"], [u / abs(force) for u in s[key]], grid)
            u_r = u_ref[:len(grid)]
            peak_ref = max(range(len(u_r)), key=lambda k: abs(u_r[k]))
            peak = max(range(len(ours)), key=lambda k: abs(ours[k]))
            misfit = max(abs(a - b) for a, b in zip(ours, u_r)) / abs(u_r[peak_ref])
            rows.append((name, comp, misfit, (grid[peak], ours[peak]),
                         (grid[peak_ref], u_r[peak_ref])))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run")
    ap.add_argument("--ref", default=DEFAULT_REF)
    ap.add_argument("--force", type=float, default=1e9, help="the run's force magnitude, N/m")
    ap.add_argument("--check", type=float, default=None, help="largest misfit allowed (fraction)")
    a = ap.parse_args()
    rows = compare(a.run, a.ref, a.force)
    print("receiver component misfit  peak_time peak_value  ref_peak_time ref_peak_value")
    worst = 0.0
    for name, comp, misfit, (tp, up), (tr, ur) in rows:
        worst = max(worst, misfit)
        print(f"{name} {comp} {100 * misfit:7.3f}%  {tp:.4f} {up: .4e}  {tr:.4f} {ur: .4e}")
        print(f"lamb.{name}.{comp}.misfit={misfit:.6f}")
    t_ref, refs = read_reference(a.ref)
    dt = t_ref[1] - t_ref[0]
    for name in ("R1", "R2"):
        s = read_csv(os.path.join(a.run, "stations", name + ".csv"))
        for comp, key, u_ref in (("ux", "ux", refs[name][0]), ("uz", "uy", refs[name][1])):
            ours = resample(s["time"], [u / abs(a.force) for u in s[key]], t_ref)
            print(f"lamb.{name}.{comp}.delay_ms={1e3 * delay(ours, u_ref, dt):.1f}")
    print(f"lamb.largest_misfit={worst:.6f}")
    if a.check is not None and worst > a.check:
        print(f"FAIL: largest misfit {100 * worst:.3f}% exceeds {100 * a.check:.3f}%")
        sys.exit(1)


if __name__ == "__main__":
    main()
