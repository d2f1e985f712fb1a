#!/usr/bin/env python3
"""A resumed run does not depend on its table_file after the start (the checkpoint stores the
merged input with the tables inline).

usage: check_table_resume.py RUPTURE WORK_DIR

A strip loaded by a traction whose factor is a CSV table (values with 17 significant digits, so
an inexact echo would show): run it uninterrupted; run it again, stopped after 60 steps with a
checkpoint; change the CSV; resume. history.csv and crack-free outputs must equal the
uninterrupted run byte for byte. Then the same with the CSV deleted.
"""
import os
import shutil
import subprocess
import sys

CASE = """
title = "strip under a tabulated traction"
[materials.homalite]
youngs_modulus = 5.2e9
poisson_ratio = 0.34
density = 1246.0
[grid]
min = [0.0, 0.0]
max = [0.02, 0.004]
cell_size = 0.5e-3
[bodies.strip]
material = "homalite"
min = [0.0, 0.0]
max = [0.02, 0.004]
[time]
end = 6e-6
[boundary.bottom]
edge = "bottom"
component = "y"
velocity = 0.0
[boundary.top]
edge = "top"
component = "y"
velocity = 0.0
[loads.push]
type = "traction"
from = [0.0, 0.0]
to = [0.0, 0.004]
normal = -10e6
function = "table"
table_file = "pulse.csv"
[output]
history_interval = 0.1e-6
snapshot_interval = 0
"""
PULSE = "time,value\n0,0\n3.3333333333333333e-7,0.91234567890123456\n2.1e-6,1.0000000000000002\n4e-6,0.3\n"
OTHER = "time,value\n0,0\n1e-6,5\n"


def fail(msg):
    print(f"FAIL: {msg}")
    sys.exit(1)


def run(args, expect_rc):
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != expect_rc:
        fail(f"{' '.join(args)}: exit {p.returncode}, expected {expect_rc}\n{p.stdout}\n{p.stderr}")
    return p


def main():
    rupture, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    case = os.path.join(work, "case.toml")
    pulse = os.path.join(work, "pulse.csv")
    with open(case, "w") as f:
        f.write(CASE)
    base = ["--quiet", "--set", "solver.threads=1"]
    with open(pulse, "w") as f:
        f.write(PULSE)
    ref = os.path.join(work, "ref")
    run([rupture, "run", case, "-o", ref] + base, 0)
    with open(os.path.join(ref, "history.csv")) as f:
        expected = f.read()
    for change in ("edited", "deleted"):
        with open(pulse, "w") as f:
            f.write(PULSE)
        d = os.path.join(work, change)
        run([rupture, "run", case, "-o", d, "--checkpoint-interval", "1e-6", "--stop-after-steps", "60"]
            + base, 4)
        if change == "edited":
            with open(pulse, "w") as f:
                f.write(OTHER)
        else:
            os.remove(pulse)
        run([rupture, "resume", d, "--quiet"], 0)
        with open(os.path.join(d, "history.csv")) as f:
            got = f.read()
        if got != expected:
            fail(f"resumed with the CSV {change}: history.csv differs from the uninterrupted run")
        print(f"CSV {change} before resume: history.csv identical ({len(got.splitlines())} lines)")
    print("PASS")


if __name__ == "__main__":
    main()
