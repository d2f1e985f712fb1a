#!/usr/bin/python3
"""John-Shah (examples/john_shah.toml, docs/validation.md): the offset-notched beam under impact
fails from the notch when the notch is near the mid-span and at the mid-span when it is far
(the experiments' transition near gamma = 0.77). Runs gamma = 0.5 and 0.85 at the example's
1.016 mm cells until the crack that runs has crossed the beam and checks, per offset:
  - which crack ran: its grown path reaches the top face (76.2 mm), the other grows less than 10 mm;
  - at gamma = 0.5 the notch crack heads for the load (its end between the notch and the
    mid-span, its chord 45 to 75 degrees from the beam's axis);
  - at gamma = 0.85 the mid-span crack runs straight up (its end within 2 mm of the mid-span:
    the beam's symmetry line, but for the notch far off it);
  - the energy balance closes within 1 %.
About 40 s on 2 cores (label long: the offset sweep is scripts/john_shah_study.py).
Usage: check_john_shah.py RUPTURE WORK_DIR"""
import csv
import json
import math
import os
import subprocess
import sys

rupture, work = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "..", "examples", "john_shah.toml")
depth, notch_depth, mid, half_span = 0.0762, 0.019, 0.1143, 0.1016
failures = []


def path(out, name):
    with open(os.path.join(out, f"crack_path_{name}.csv")) as f:
        return [(float(r["time"]), float(r["x"]), float(r["y"])) for r in csv.DictReader(f)]


for gamma, end, runs in ((0.5, 0.9e-3, "notch"), (0.85, 1.05e-3, "seed")):
    out = os.path.join(work, f"gamma_{gamma:g}")
    subprocess.run([rupture, "run", example, "-o", out, "--overwrite", "--quiet",
                    "--set", f"parameters.offset={gamma!r}", "--set", f"time.end={end!r}"],
                   check=True, stdout=subprocess.DEVNULL)
    r = json.load(open(os.path.join(out, "run.json")))
    ran = path(out, runs)
    x0 = mid - gamma * half_span if runs == "notch" else mid
    y0 = notch_depth if runs == "notch" else 0.0
    top = ran[-1][2] if ran else 0.0
    other_name = "seed" if runs == "notch" else "notch"
    other_grown = r[f"cracks.{other_name}.length"]
    angle = math.degrees(math.atan2(ran[-1][2] - y0, ran[-1][1] - x0)) if ran else math.nan
    err = r["energy_balance_error"]
    print(f"gamma {gamma}: {runs} crack ends at ({ran[-1][1] * 1e3:.2f}, {top * 1e3:.2f}) mm at "
          f"{ran[-1][0] * 1e6:.1f} us, chord {angle:.1f} deg; the {other_name} crack grew {other_grown * 1e3:.2f} mm; "
          f"energy error {err:.2e}; {r['steps']} steps, {r['wall_seconds']:.1f} s")
    if top < depth - 1e-9:
        failures.append(f"gamma {gamma}: the {runs} crack did not reach the top face (y = {top:.4f} m)")
    if other_grown > 0.010:
        failures.append(f"gamma {gamma}: the {other_name} crack grew {other_grown:.4f} m (bound 0.010)")
    if runs == "notch" and not (x0 < ran[-1][1] < mid and 45.0 <= angle <= 75.0):
        failures.append(f"gamma {gamma}: the notch crack ends at x = {ran[-1][1]:.4f} m, chord {angle:.1f} deg "
                        f"(expected between the notch and the mid-span, 45 to 75 deg)")
    if runs == "seed" and abs(ran[-1][1] - mid) > 0.002:
        failures.append(f"gamma {gamma}: the mid-span crack ends {abs(ran[-1][1] - mid):.4f} m off the mid-span")
    if err > 0.01:
        failures.append(f"gamma {gamma}: energy balance error {err:.3g} (bound 0.01)")

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("John-Shah: the notch near the mid-span fails at the notch, far from it the mid-span fails")
