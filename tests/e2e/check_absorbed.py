#!/usr/bin/python3
"""What an absorbing edge leaves behind, on nested levels and on the uniform finest grid:

  check_absorbed.py NESTED UNIFORM LIMIT BOUND

The energy left in the bodies at the end (kinetic + strain, history.csv's last row), once the
pulse has passed the absorbing edge, over the energy the load put in (the most external work
reached): on nested levels at most LIMIT (the single grid's criterion, tests/verification/
test_absorbing.cpp: 2 % for a pulse of 16 cells or more), and within BOUND of the uniform run's
(the levels' dashpots together act as one lattice's)."""
import csv
import sys


def left(d):
    rows = list(csv.DictReader(open(f"{d}/history.csv")))
    put_in = max(float(r["external_work"]) for r in rows)
    last = rows[-1]
    return (float(last["kinetic_energy"]) + float(last["strain_energy"])) / put_in, float(last["time"])


(n, tn), (u, tu) = left(sys.argv[1]), left(sys.argv[2])
limit, bound = float(sys.argv[3]), float(sys.argv[4])
ok = abs(tn - tu) < 1e-9 and n <= limit and abs(n - u) <= bound
print(f"left at t = {1e6 * tn:.2f} us: nested {100 * n:.3f} %, uniform {100 * u:.3f} % of the energy put in "
      f"(limits: {100 * limit:.1f} %, difference {100 * bound:.2f} %) {'ok' if ok else 'FAILED'}")
sys.exit(0 if ok else 1)
