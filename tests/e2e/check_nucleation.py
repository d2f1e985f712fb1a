#!/usr/bin/python3
"""A crack that nucleates at its drawn line once the stress across it reaches the strength
(interface.NAME.nucleation = "strength"; solver/crack_nucleation.hpp; docs/fracture.md,
"Nucleation at a drawn site"). tests/inputs/nucleation_site.toml: a 4 mm line at 30 degrees in a
prestressed plate whose normal stress across the line is `ratio` times the strength. Checks:
  1. ratio = 0.99: the line stays intact to the end (run.json nucleation_time null, the CLI says
     "did not nucleate"), and the plate moves as the plate without the line does: the stations
     0.75 mm either side of the line's middle equal to round-off (1e-9 of their largest
     displacement; measured: to the bit). The body split along the line and tied over it is the
     undivided plate: the tie takes every node a particle within half a cell of the line reaches,
     beyond the ends on the free edges too (docs/fracture.md, "The tie's reach"; with the tie's
     earlier reach, the support without the particles' half-width, they differed by 0.09 %). Control: the same line
     drawn as a plain pre-crack (no nucleation) opens across its middle by more than twice the
     intact line's largest (measured 5.6 um against 1.5 um, the strain between the stations as the
     release waves pass);
  2. ratio = 1.01: the line comes loose at the first step (nucleation_time = the first step's
     end) and opens as a crack suddenly cut under that stress: the opening across its middle
     passes 4 um (measured 5.6 um at 5 us; the static opening of a crack of length 2a under
     sigma_nn is 4 sigma_nn a (1 - nu^2) / E = 4.3 um plus the 0.75 mm of strain either side,
     and a suddenly cut crack overshoots it);
  3. the same stress turned with the line: the line at 30 + 90 degrees (its normal turned by
     90 degrees, the stress too) comes loose at ratio 1.01 and not at 0.99 (the criterion reads
     the stress across the line, not a component in the grid's axes).
Set LAUNCH (e.g. "mpiexec -n 2") to run under it.
Usage: check_nucleation.py RUPTURE CASE WORK_DIR"""
import csv
import json
import math
import os
import re
import shlex
import subprocess
import sys

rupture, case, work = sys.argv[1:4]
launch = shlex.split(os.environ.get("LAUNCH", ""))
os.makedirs(work, exist_ok=True)
failures = []


def run(name, *sets, path=case):
    out = os.path.join(work, name)
    args = launch + [rupture, "run", path, "-o", out, "--overwrite", "--quiet"]
    for s in sets:
        args += ["--set", s]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"FAIL: {name}: rupture exited {done.returncode}:\n{done.stderr}")
    return out, json.load(open(os.path.join(out, "run.json"))), done.stdout


def stations(out, name):
    with open(os.path.join(out, "stations", f"{name}.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def opening(out, degrees=30.0):
    n = (-math.sin(math.radians(degrees)), math.cos(math.radians(degrees)))
    a, b = stations(out, "above"), stations(out, "below")
    return [(ra["time"], (ra["ux"] - rb["ux"]) * n[0] + (ra["uy"] - rb["uy"]) * n[1]) for ra, rb in zip(a, b)]


# 1. Below the strength: intact, and the plate as without the line.
below, rb, cli = run("below", "parameters.ratio=0.99")
if rb.get("cracks.site.nucleation_time") is not None:
    failures.append(f"ratio 0.99: the line came loose at {rb['cracks.site.nucleation_time']} s")
if "crack site: did not nucleate" not in cli or not re.search(r"crack\.site\.nucleation_time=-1", cli):
    failures.append("ratio 0.99: the CLI does not say the line did not nucleate")
text = open(case).read()
plain = re.sub(r"\[interface\.site\].*?(?=\n\[)", "", text, flags=re.S)
plain_path = os.path.join(work, "no_line.toml")
open(plain_path, "w").write(plain)
undivided, _, _ = run("no_line", path=plain_path)
worst, largest = 0.0, 0.0
for name in ("above", "below"):
    for a, b in zip(stations(below, name), stations(undivided, name)):
        for k in ("ux", "uy"):
            worst = max(worst, abs(a[k] - b[k]))
            largest = max(largest, abs(b[k]))
print(f"ratio 0.99: intact; stations against the plate without the line: {worst:.3g} m of {largest:.3g} m "
      f"({worst / largest * 100:.2f} %)")
if not worst <= 1e-9 * largest:
    failures.append(f"ratio 0.99: stations differ from the undivided plate's by {worst:.3g} m (bound round-off, 1e-9 of {largest:.3g})")

# The control: the same line drawn as a plain pre-crack (no nucleation) is cut from the start.
cut_path = os.path.join(work, "cut.toml")
open(cut_path, "w").write(re.sub(r"\nnucleation(_strength)? = [^\n]*", "", text))
cut, _, _ = run("cut", "parameters.ratio=0.99", path=cut_path)
cut_peak = max(o for _, o in opening(cut))
intact_peak = max(abs(o) for _, o in opening(below))
print(f"ratio 0.99: largest opening across the line {intact_peak * 1e6:.3f} um (the strain between the stations); "
      f"drawn as a plain pre-crack {cut_peak * 1e6:.3f} um")
if not cut_peak > 2.0 * intact_peak:
    failures.append(f"the control (a plain pre-crack) opened by {cut_peak:.3g} m only, against {intact_peak:.3g} m intact")

# 2. Above the strength: loose at the first step, then open as a cut crack.
above, ra, cli = run("above", "parameters.ratio=1.01")
t = ra.get("cracks.site.nucleation_time")
print(f"ratio 1.01: came loose at {t} s (dt {ra['dt']:.4g} s)")
if t is None or not (0.0 < t <= 1.5 * ra["dt"]):
    failures.append(f"ratio 1.01: nucleation_time {t}, expected the first step's end ({ra['dt']:.4g} s)")
if "crack site: nucleated at" not in cli:
    failures.append("ratio 1.01: the CLI does not say when the line nucleated")
peak = max(o for _, o in opening(above))
print(f"ratio 1.01: largest opening across the line {peak * 1e6:.3f} um")
if not peak > 4e-6:
    failures.append(f"ratio 1.01: the loose line opened by {peak:.3g} m only (expected above 4 um)")

# 3. The line and the stress turned by 90 degrees together.
turned = ["parameters.c=-0.5", "parameters.s=0.8660254037844387"]
_, r99, _ = run("turned_below", "parameters.ratio=0.99", *turned)
_, r101, _ = run("turned_above", "parameters.ratio=1.01", *turned)
print(f"turned by 90 degrees: ratio 0.99 -> {r99.get('cracks.site.nucleation_time')}, "
      f"1.01 -> {r101.get('cracks.site.nucleation_time')}")
if r99.get("cracks.site.nucleation_time") is not None or r101.get("cracks.site.nucleation_time") != t:
    failures.append("turned by 90 degrees: the line does not come loose as the unturned one does")

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("a drawn site stays intact below the strength and comes loose at it, read across the line")
