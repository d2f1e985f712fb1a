#!/usr/bin/python3
"""Resolution study of examples/kalthoff_winkler.toml (docs/validation.md, "Kalthoff-Winkler"):
runs it at the cell sizes given (default 1, 0.5, 0.25 mm) to 75 us and prints, per size, the
initiation time, the first segment's angle, the path's mean angle to the notch over its straight
stretch (from 5 mm past the tip to y = 85 mm), where and when it reaches the far edge, its mean
speed from initiation to there, the grown length, steps and wall time, and the speed over the
middle of the path (20 to 60 mm grown); then each path's largest
distance from the finest one's. Experiments (Kalthoff & Winkler 1988, as quoted by Belytschko et
al. 2003 and Borden et al. 2012): about 70 degrees.
Usage: kalthoff_winkler_study.py RUPTURE WORK_DIR [CELL_SIZES...] (KW_END=SECONDS: another end time;
KW_SET="KEY=VALUE ...": more --set options, e.g. KW_SET=interface.notch.running_tip=true)"""
import json
import math
import os
import subprocess
import sys

import numpy as np

rupture, work = sys.argv[1], sys.argv[2]
sizes = [float(v) for v in sys.argv[3:]] or [1e-3, 0.5e-3, 0.25e-3]
end = float(os.environ.get("KW_END", "75e-6"))  # s
extra = [a for kv in os.environ.get("KW_SET", "").split() for a in ("--set", kv)]
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "examples", "kalthoff_winkler.toml")
tip0 = np.array([0.05, 0.025])
paths = {}
print("h_mm initiation_us first_deg mean_deg edge_x_mm edge_time_us speed_m_s grown_mm steps wall_s mid_speed_m_s")
for h in sizes:
    out = os.path.join(work, f"h_{h * 1e3:g}mm")
    subprocess.run([rupture, "run", example, "-o", out, "--overwrite", "--quiet",
                    "--set", f"grid.cell_size={h!r}", "--set", f"interface.notch.segments={round(0.05 / h)}",
                    "--set", f"time.end={end!r}", *extra], check=True, stdout=subprocess.DEVNULL)
    r = json.load(open(os.path.join(out, "run.json")))
    d = np.genfromtxt(os.path.join(out, "crack_path_notch.csv"), delimiter=",", names=True)
    p = np.vstack([tip0, np.column_stack([d["x"], d["y"]])])
    paths[h] = p
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(p, axis=0), axis=1))])
    straight = (s >= 5e-3) & (p[:, 1] <= 0.085)
    q = p[straight]
    mean = math.degrees(math.atan2(q[-1, 1] - q[0, 1], q[-1, 0] - q[0, 0])) if len(q) > 1 else float("nan")
    at_edge = p[-1, 1] >= 0.1 - 1e-9 or p[-1, 0] >= 0.1 - 1e-9
    t_edge = d["time"][-1] if at_edge else float("nan")
    speed = s[-1] / (t_edge - d["time"][0]) if at_edge else float("nan")
    # Over the middle of the path (20 to 60 mm grown): away from the start and from the far edge,
    # where a tip within a cell of the edge cuts through to it (a jump of up to a cell).
    grown = np.cumsum(d["length"])
    mid = (grown >= 20e-3) & (grown <= 60e-3)
    mid_speed = ((grown[mid][-1] - grown[mid][0]) / (d["time"][mid][-1] - d["time"][mid][0])
                 if mid.sum() > 2 else float("nan"))
    print(f"{h * 1e3:4g} {r['cracks.notch.initiation_time'] * 1e6:13.2f} {r['cracks.notch.initial_angle']:9.2f} "
          f"{mean:8.2f} {p[-1, 0] * 1e3 if at_edge else float('nan'):9.2f} {t_edge * 1e6:12.2f} {speed:9.0f} "
          f"{r['cracks.notch.length'] * 1e3:8.2f} {r['steps']:5d} {r['wall_seconds']:6.1f} {mid_speed:13.0f}")
finest = paths[min(sizes)]


def distance(pt, line):
    best = math.inf
    for a, b in zip(line[:-1], line[1:]):
        v = b - a
        t = np.clip(np.dot(pt - a, v) / max(np.dot(v, v), 1e-300), 0, 1)
        best = min(best, np.linalg.norm(pt - (a + t * v)))
    return best


for h in sizes:
    if h == min(sizes):
        continue
    dev = max(distance(pt, finest) for pt in paths[h] if pt[1] <= 0.085)
    print(f"h = {h * 1e3:g} mm: path within {dev * 1e3:.2f} mm of the {min(sizes) * 1e3:g} mm path (up to y = 85 mm)")
