#!/usr/bin/python3
"""A case on nested levels against the same case on the uniform grid at the finest cell size
(and, as the yardstick of what refinement costs, on the graded grid the benchmark tests accept):

  check_levels_match_uniform.py NESTED UNIFORM GRADED LIMIT [COLUMN ...]

For each history.csv column (default kinetic_energy, strain_energy, external_work) the largest
difference over the run from the uniform run's, relative to that column's largest magnitude,
must be at most LIMIT and at most the graded grid's own difference (nested levels are no less
accurate than the graded grid they replace). The nested run's energy balance (E14) at the end
must be no worse than 1.1 times the uniform run's: a load whose force or work were lost at
the transitions would show there."""
import csv
import sys


def history(d):
    rows = list(csv.DictReader(open(f"{d}/history.csv")))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


nested, uniform, graded = (history(d) for d in sys.argv[1:4])
limit = float(sys.argv[4])
columns = sys.argv[5:] or ["kinetic_energy", "strain_energy", "external_work"]
ok = len(nested["time"]) == len(uniform["time"]) == len(graded["time"])
if not ok:
    print(f"sample counts differ: {len(nested['time'])}, {len(uniform['time'])}, {len(graded['time'])}")
for c in columns:
    scale = max(abs(v) for v in uniform[c]) or 1.0
    dn = max(abs(a - b) for a, b in zip(nested[c], uniform[c])) / scale
    dg = max(abs(a - b) for a, b in zip(graded[c], uniform[c])) / scale
    good = dn <= limit and dn <= dg
    ok = ok and good
    print(f"{c}: nested differs from uniform by {100 * dn:.3f} % of its largest value, graded by "
          f"{100 * dg:.3f} % (limit {100 * limit:.2f} %) {'ok' if good else 'FAILED'}")
bn, bu = nested["relative_balance_error"][-1], uniform["relative_balance_error"][-1]
good = abs(bn) <= 1.1 * abs(bu)
ok = ok and good
print(f"energy balance at the end: nested {100 * bn:.3f} %, uniform {100 * bu:.3f} % {'ok' if good else 'FAILED'}")
sys.exit(0 if ok else 1)
