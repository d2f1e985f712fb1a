#!/usr/bin/python3
"""Offset sweep of examples/john_shah.toml (docs/validation.md, "John-Shah"): runs the beam at
each notch offset gamma (a fraction of the half-span) and prints which crack ran through the
beam (its path reaches the top tenth of the depth by the end: through, or arrested just below the
top face in the load's compression), the notch crack's and the mid-span seed's grown lengths, when each started and when the
one that ran reached the top face, the notch crack's mean angle to the beam's axis (the chord
from the notch tip to its end, degrees from horizontal, towards the mid-span), steps and wall
time (the angle only where the notch failed), and when the mid-span site nucleated (with
interface.seed.nucleation = "strength"; nan: it stayed intact, or is a drawn seed). Extra --set options (the cell size, the seed's length) go after the offsets, after '--'.
Experiments (John & Shah 1990, as quoted by the Abaqus Benchmarks Guide 1.19.3 and Belytschko et
al. 2003): the beam fails from the notch below an offset near gamma = 0.77 and at the mid-span
above it.
Usage: john_shah_study.py RUPTURE WORK_DIR [OFFSETS...] [-- KEY=VALUE ...]"""
import csv
import json
import math
import os
import subprocess
import sys

rupture, work = sys.argv[1], sys.argv[2]
rest = sys.argv[3:]
sets = rest[rest.index("--") + 1:] if "--" in rest else []
offsets = [float(v) for v in (rest[:rest.index("--")] if "--" in rest else rest)] or \
    [0.5, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9]
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "examples", "john_shah.toml")
depth, notch_depth, mid, half_span = 0.0762, 0.019, 0.1143, 0.1016


def path(out, name):
    with open(os.path.join(out, f"crack_path_{name}.csv")) as f:
        return [(float(r["time"]), float(r["x"]), float(r["y"])) for r in csv.DictReader(f)]


def us(t):  # a crack that never grew (or nucleated) has no such time (null, or absent, in run.json)
    return math.nan if t is None else t * 1e6


print("gamma failure notch_mm seed_mm notch_start_us seed_start_us through_us notch_angle_deg steps wall_s "
      "seed_nucleated_us")
for g in offsets:
    tag = "_".join(s.replace("=", "-") for s in sets)
    out = os.path.join(work, f"gamma_{g:g}" + (f"_{tag}" if tag else ""))
    args = [rupture, "run", example, "-o", out, "--overwrite", "--quiet", "--set", f"parameters.offset={g!r}"]
    for s in sets:
        args += ["--set", s]
    # A run that stops with a diagnosis (a junction the fields cannot hold, after one crack is
    # through) keeps what it wrote: its outcome is read from that, and the stop is printed.
    done = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    r = json.load(open(os.path.join(out, "run.json")))
    if done.returncode != 0 and r.get("status") != "failed":
        sys.exit(f"gamma {g}: rupture exited {done.returncode}: {done.stderr}")
    notch, seed = path(out, "notch"), path(out, "seed")
    top = lambda p: bool(p) and p[-1][2] >= 0.9 * depth  # through, or arrested in the last tenth
    failure = "notch" if top(notch) and not top(seed) else "mid-span" if top(seed) and not top(notch) else \
        "both" if top(notch) else "none"
    ran = notch if failure == "notch" else seed
    through = ran[-1][0] if failure in ("notch", "mid-span") and ran[-1][2] >= depth - 1e-9 else math.nan
    x0 = mid - g * half_span
    angle = math.degrees(math.atan2(notch[-1][2] - notch_depth, notch[-1][1] - x0)) \
        if failure in ("notch", "both") else math.nan
    print(f"{g:5.2f} {failure:>8} {r['cracks.notch.length'] * 1e3:8.2f} {r['cracks.seed.length'] * 1e3:7.2f} "
          f"{us(r['cracks.notch.initiation_time']):14.1f} {us(r['cracks.seed.initiation_time']):13.1f} "
          f"{through * 1e6:10.1f} {angle:15.1f} {r['steps']:5d} {r['wall_seconds']:6.1f} "
          f"{us(r.get('cracks.seed.nucleation_time')):17.1f}"
          + (f"  (stopped at {r['simulated_time'] * 1e6:.1f} us: {r['message'].split(' at t')[0]})"
             if r.get("status") == "failed" else ""), flush=True)
