#!/usr/bin/env python3
"""`mpirun -n N rupture run` writes the run directory one process writes, to round-off.

Usage: check_mpi_run.py SERIAL_DIR DISTRIBUTED_DIR RANKS BOUND
history.csv: the same sample times, and kinetic energy, strain energy, external work and (where
the run has interfaces) the cohesive stored and dissipated energies equal to BOUND relative to
each column's largest magnitude; crack_tip.csv and the last interface
profile, every interface's last profile and crack_tip_NAME.csv and the Mach-angle readings value by value, to BOUND of each column's largest
magnitude (nan, a side not measured, on both); every growing crack's path (crack_path_NAME.csv)
and every tip's J and K (stress_intensity_NAME.csv) value by value, positions to BOUND of the
largest coordinate and K_I, K_II of the larger K (a K_II that is round-off of zero in mode I has
no digits of its own); run.json: status completed, "ranks" equal to RANKS, the same steps, every
cracks.NAME.KEY to BOUND.
"""
import csv
import json
import math
import sys

a_dir, b_dir, ranks, bound = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4])
ok = True


def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and cond


def rows(d):
    with open(f"{d}/history.csv") as f:
        return list(csv.DictReader(f))


a, b = rows(a_dir), rows(b_dir)
check(len(a) == len(b) and len(a) > 2, f"{len(a)} and {len(b)} history samples")
for col in ("time", "kinetic_energy", "strain_energy", "external_work", "cohesive_stored", "cohesive_dissipated"):
    if col not in a[0]:
        continue
    scale = max(abs(float(r[col])) for r in a) or 1.0
    diff = max(abs(float(x[col]) - float(y[col])) for x, y in zip(a, b))
    check(diff <= bound * scale, f"{col}: largest difference {diff / scale:.2e} of its largest value (bound {bound:g})")
# Interfaces: the crack tip's history and the last interface profile, value by value.
import glob
import os
# Every interface's own crack file too (crack_tip_NAME.csv: the runs of several interfaces).
named = sorted(os.path.basename(f) for f in glob.glob(f"{a_dir}/crack_tip_*.csv"))
# ... and every interface's last profile (interface/NAME_NNNNNN.csv).
last = {}
for f in sorted(glob.glob(f"{a_dir}/interface/*_[0-9][0-9][0-9][0-9][0-9][0-9].csv")):
    last[os.path.basename(f)[:-11]] = "interface/" + os.path.basename(f)
for name in ["crack_tip.csv", "interface/interface_000004.csv", "mach_angle.csv"] + named + sorted(set(last.values())):
    try:
        ta, tb = open(f"{a_dir}/{name}").read(), open(f"{b_dir}/{name}").read()
    except FileNotFoundError:
        continue
    ra_, rb_ = list(csv.reader(ta.splitlines())), list(csv.reader(tb.splitlines()))
    same_shape = len(ra_) == len(rb_) and all(len(x) == len(y) for x, y in zip(ra_, rb_))
    # Each value to BOUND of its column's largest magnitude (a value that is round-off of zero,
    # the jump at a bonded end, has no digits to compare on its own); text columns equal.
    worst = 0.0
    if same_shape:
        scale = [0.0] * len(ra_[0])
        for x in ra_[1:]:
            for k, u in enumerate(x):
                try:
                    if not math.isnan(float(u)):
                        scale[k] = max(scale[k], abs(float(u)))
                except ValueError:
                    pass
        for x, y in zip(ra_[1:], rb_[1:]):
            for k, (u, v) in enumerate(zip(x, y)):
                try:
                    fu, fv = float(u), float(v)
                except ValueError:
                    worst = max(worst, 0.0 if u == v else 1.0)
                    continue
                if math.isnan(fu) or math.isnan(fv):  # a side not measured: on both
                    worst = max(worst, 0.0 if math.isnan(fu) and math.isnan(fv) else 1.0)
                    continue
                worst = max(worst, abs(fu - fv) / (scale[k] or 1e-300))
    check(same_shape and worst <= bound, f"{name}: {len(ra_)} rows, largest difference {worst:.2e} of its column's largest value")
# Crack paths and tips: columns that share a scale (positions; the two K) share it.
shared = ({"x", "y"}, {"K_I", "K_II"})
for path in sorted(glob.glob(f"{a_dir}/crack_path_*.csv") + glob.glob(f"{a_dir}/stress_intensity_*.csv")):
    name = os.path.basename(path)
    sa = list(csv.DictReader(open(path)))
    try:
        sb = list(csv.DictReader(open(f"{b_dir}/{name}")))
    except FileNotFoundError:
        check(False, f"{name}: missing from {b_dir}")
        continue
    worst = 0.0
    if sa and len(sa) == len(sb):
        scale = {col: max(abs(float(r[col])) for r in sa) for col in sa[0].keys()}
        for group in shared:
            if group <= scale.keys():
                top = max(scale[c] for c in group)
                for c in group:
                    scale[c] = top
        for col in sa[0].keys():
            worst = max(worst, max(abs(float(x[col]) - float(y[col])) for x, y in zip(sa, sb)) / (scale[col] or 1.0))
    check(len(sa) == len(sb) and worst <= bound,
          f"{name}: {len(sa)} and {len(sb)} rows, largest difference {worst:.2e} of its column's largest value")
# Stations: each column to BOUND of its largest magnitude.
for path in sorted(glob.glob(f"{a_dir}/stations/*.csv")):
    name = os.path.basename(path)
    sa = list(csv.DictReader(open(path)))
    sb = list(csv.DictReader(open(f"{b_dir}/stations/{name}")))
    worst = 0.0
    for col in sa[0].keys():
        scale = max(abs(float(r[col])) for r in sa) or 1.0
        worst = max(worst, max(abs(float(x[col]) - float(y[col])) for x, y in zip(sa, sb)) / scale)
    check(len(sa) == len(sb) and worst <= bound, f"stations/{name}: {len(sa)} rows, largest difference {worst:.2e} of a column's largest value")
ra, rb = json.load(open(f"{a_dir}/run.json")), json.load(open(f"{b_dir}/run.json"))
check(rb["status"] == "completed", f"status {rb['status']}")
check(rb.get("ranks") == ranks and ra.get("ranks") == 1, f"ranks {ra.get('ranks')} and {rb.get('ranks')}")
check(ra["steps"] == rb["steps"], f"steps {ra['steps']} and {rb['steps']}")
for key in sorted(k for k in ra if k.startswith("cracks.")):
    x, y = ra[key], rb.get(key)
    check(y is not None and abs(x - y) <= bound * max(abs(x), 1e-300) if x else y == x, f"{key}: {x} and {y}")
if "crack" in ra:
    for key in ("initiation_time", "sustained_speed", "final_tip"):
        x, y = ra["crack"][key], rb["crack"][key]
        if x is None or y is None:  # null: never happened (no initiation)
            check(x is None and y is None, f"crack.{key}: {x} and {y}")
            continue
        check(abs(x - y) <= bound * max(abs(x), 1e-300), f"crack.{key}: {x} and {y}")
sys.exit(0 if ok else 1)
