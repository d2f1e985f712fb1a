#!/usr/bin/env python3
"""Station table of TPV205-2D runs (examples/tpv205_2d.toml): for each station along strike the
rupture time (first slip rate above 1 mm/s, the SCEC definition), the peak slip rate and the final
slip; one column group per run (a resolution study passes several), with the run's particle count,
steps and wall time. Usage: tpv205_table.py RUN_DIR [RUN_DIR ...]"""
import sys

import numpy as np

STATIONS = [("st_m12", -12.0), ("st_m7p5", -7.5), ("st_m4p5", -4.5), ("st0", 0.0),
            ("st_p4p5", 4.5), ("st_p7p5", 7.5), ("st_p12", 12.0)]


def station(run, name, x_km):
    """Rupture time from the nodes' profile (rupture_time_fault.csv: the slip path's rate, so
    the stick spring's elastic jump, which passing waves load, does not count), interpolated at
    the station; peak slip rate and final slip from the station's record."""
    d = np.loadtxt(f"{run}/stations/{name}.csv", delimiter=",", skiprows=1)
    slip, rate = d[:, 1], np.abs(d[:, 2])
    prof = np.genfromtxt(f"{run}/rupture_time_fault.csv", delimiter=",", names=True)
    rt = float(np.interp(1e3 * x_km, prof["x"], prof["rupture_time"]))
    return rt, rate.max(), slip[-1]


runs = sys.argv[1:]
head = "| station (km) |"
rule = "|---|"
for run in runs:
    label = run.rstrip("/").split("/")[-1]
    head += f" {label}: rupture time (s) | peak slip rate (m/s) | final slip (m) |"
    rule += "---|---|---|"
print(head)
print(rule)
for name, x in STATIONS:
    line = f"| {x:+.1f} |"
    for run in runs:
        rt, pr, fs = station(run, name, x)
        line += f" {rt:.3f} | {pr:.3f} | {fs:.3f} |"
    print(line)
for run in runs:
    log = open(f"{run}.log").read() if run.endswith(("h200", "h100", "h50")) else ""
    vals = dict(l.split("=", 1) for l in log.splitlines() if "=" in l and l.split("=", 1)[0] in
                ("particles", "steps", "wall_seconds"))
    print(f"{run}: particles={vals.get('particles', '?')} steps={vals.get('steps', '?')} "
          f"wall_seconds={vals.get('wall_seconds', '?')}")
