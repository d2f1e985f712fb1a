#!/usr/bin/python3
"""A run stopped after STEPS steps (--stop-after-steps: the checkpoint written, exit 4) and
resumed equals the uninterrupted run REF byte for byte: every CSV file REF holds (history,
crack tip, stations), for cases without a crack too (check_restart.py covers a cohesive one).

  check_resume_bitwise.py RUPTURE CASE REF WORK STEPS [-- RUN_ARGS...]"""
import filecmp
import glob
import os
import shutil
import subprocess
import sys

rupture, case, ref, work, steps = sys.argv[1:6]
args = sys.argv[7:] if len(sys.argv) > 6 and sys.argv[6] == "--" else []
shutil.rmtree(work, ignore_errors=True)
r = subprocess.run([rupture, "run", case, "-o", work, "--quiet", "--stop-after-steps", steps] + args,
                   capture_output=True, text=True)
if r.returncode != 4:
    sys.exit(f"FAIL: stopped run exited {r.returncode}, expected 4:\n{r.stderr}")
r = subprocess.run([rupture, "resume", work, "--quiet"], capture_output=True, text=True)
if r.returncode != 0:
    sys.exit(f"FAIL: resume exited {r.returncode}:\n{r.stderr}")
names = sorted(os.path.relpath(p, ref) for p in glob.glob(f"{ref}/**/*.csv", recursive=True))
bad = [n for n in names if not os.path.exists(os.path.join(work, n)) or
       not filecmp.cmp(os.path.join(ref, n), os.path.join(work, n), shallow=False)]
print(f"stopped after {steps} steps and resumed: {len(names) - len(bad)} of {len(names)} CSV files identical "
      f"to the uninterrupted run's{': differ: ' + ', '.join(bad) if bad else ''}")
sys.exit(1 if bad or not names else 0)
