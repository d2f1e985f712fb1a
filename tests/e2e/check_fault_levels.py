#!/usr/bin/python3
"""A slip-weakening fault on nested levels against the uniform grid at the finest cell size,
with the uniform grid at twice that cell size as the yardstick (the resolution study of
docs/faults.md):

  check_fault_levels.py NESTED UNIFORM COARSE

At every station (stations/*.csv): the rupture's arrival (slip rate first above 1 mm/s) within
0.02 s (two station samples) of the uniform run's, and the final slip and the peak slip rate no
further from the uniform run's than the coarse run's are, and the final slip within 1.5 %."""
import csv
import os
import sys


def read(d, f):
    rows = list(csv.DictReader(open(os.path.join(d, "stations", f))))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def arrival(s):
    return next((t for t, v in zip(s["time"], s["slip_rate"]) if v > 1e-3), float("inf"))


nested, uniform, coarse = sys.argv[1:4]
names = sorted(os.listdir(os.path.join(uniform, "stations")))
ok = bool(names) and names == sorted(os.listdir(os.path.join(nested, "stations")))
for f in names:
    n, u, c = read(nested, f), read(uniform, f), read(coarse, f)
    da = abs(arrival(n) - arrival(u))
    rel = lambda a, b: abs(a - b) / abs(b)
    slip_n, slip_c = rel(n["slip"][-1], u["slip"][-1]), rel(c["slip"][-1], u["slip"][-1])
    rate_n, rate_c = rel(max(n["slip_rate"]), max(u["slip_rate"])), rel(max(c["slip_rate"]), max(u["slip_rate"]))
    good = da <= 0.02 + 1e-9 and slip_n <= 0.015 and slip_n <= slip_c and rate_n <= rate_c
    ok = ok and good
    print(f"{f}: arrival {arrival(n):.3f} vs {arrival(u):.3f} s; final slip {100 * slip_n:.2f} % off "
          f"(coarse grid {100 * slip_c:.2f} %); peak slip rate {100 * rate_n:.2f} % off (coarse grid "
          f"{100 * rate_c:.2f} %) {'ok' if good else 'FAILED'}")
sys.exit(0 if ok else 1)
