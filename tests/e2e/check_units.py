#!/usr/bin/python3
"""Every column of every CSV file in a run directory is listed, with a unit, in DIR/units.csv
(output/csv_units.cpp), and units.csv lists nothing the files do not hold for the files present.

Usage: check_units.py RUN_DIR [RUN_DIR ...]
"""
import csv
import fnmatch
import glob
import os
import sys

ok = True
for run in sys.argv[1:]:
    table = list(csv.DictReader(open(os.path.join(run, "units.csv"))))
    files = sorted(glob.glob(os.path.join(run, "*.csv")) + glob.glob(os.path.join(run, "interface", "*.csv")))
    files = [f for f in files if os.path.basename(f) != "units.csv"]
    if not files:
        print(f"FAIL {run}: no CSV files")
        ok = False
    for path in files:
        rel = os.path.relpath(path, run)
        header = next(csv.reader(open(path)))
        listed = {r["column"]: r for r in table if fnmatch.fnmatch(rel, r["file"])}
        missing = [c for c in header if c not in listed]
        extra = [c for c in listed if c not in header]
        good = not missing and not extra and all(listed[c]["meaning"] for c in header)
        ok = ok and good
        print(("ok   " if good else "FAIL ") + f"{run}/{rel}: {len(header)} columns"
              + (f"; not in units.csv: {missing}" if missing else "")
              + (f"; in units.csv but not in the file: {extra}" if extra else ""))
sys.exit(0 if ok else 1)
