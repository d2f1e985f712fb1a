#!/usr/bin/env python3
"""`mpirun -n N rupture run` writes the run directory one process writes, to round-off.

Usage: check_mpi_run.py SERIAL_DIR DISTRIBUTED_DIR RANKS BOUND
history.csv: the same sample times, and kinetic energy, strain energy and external work equal
to BOUND relative to each column's largest magnitude; run.json: status completed, "ranks"
equal to RANKS, the same steps.
"""
import csv
import json
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
for col in ("time", "kinetic_energy", "strain_energy", "external_work"):
    scale = max(abs(float(r[col])) for r in a) or 1.0
    diff = max(abs(float(x[col]) - float(y[col])) for x, y in zip(a, b))
    check(diff <= bound * scale, f"{col}: largest difference {diff / scale:.2e} of its largest value (bound {bound:g})")
ra, rb = json.load(open(f"{a_dir}/run.json")), json.load(open(f"{b_dir}/run.json"))
check(rb["status"] == "completed", f"status {rb['status']}")
check(rb.get("ranks") == ranks and ra.get("ranks") == 1, f"ranks {ra.get('ranks')} and {rb.get('ranks')}")
check(ra["steps"] == rb["steps"], f"steps {ra['steps']} and {rb['steps']}")
sys.exit(0 if ok else 1)
