#!/usr/bin/env python3
"""A fault run stopped and resumed equals an uninterrupted one byte for byte: history, stations
(their rows are in the checkpoint), the rupture-time profile (rupture times, peak slip rates,
slip paths) and the interface profiles. Usage: check_fault_restart.py RUPTURE CASE WORK_DIR"""
import filecmp
import glob
import os
import shutil
import subprocess
import sys

rupture, case, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
ref, d = os.path.join(work, "ref"), os.path.join(work, "resumed")
subprocess.run([rupture, "run", case, "-o", ref, "--quiet"], check=True, stdout=subprocess.DEVNULL)
p = subprocess.run([rupture, "run", case, "-o", d, "--quiet", "--checkpoint-interval", "0.1",
                    "--stop-after-steps", "400"], stdout=subprocess.DEVNULL)
assert p.returncode == 4, f"stopped run exited {p.returncode}, expected 4"
subprocess.run([rupture, "resume", d, "--quiet"], check=True, stdout=subprocess.DEVNULL)
names = ["history.csv", "rupture_time_fault.csv"]
names += [os.path.relpath(f, ref) for f in glob.glob(os.path.join(ref, "stations", "*.csv"))]
names += [os.path.relpath(f, ref) for f in glob.glob(os.path.join(ref, "interface", "*.csv"))]
assert any(n.startswith("stations") for n in names), "no station files"
for n in names:
    if not filecmp.cmp(os.path.join(ref, n), os.path.join(d, n), shallow=False):
        sys.exit(f"{n} differs after the resume")
print(f"{len(names)} files equal byte for byte after a stop at step 400 and a resume")
