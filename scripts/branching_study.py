#!/usr/bin/python3
"""Resolution study of examples/dynamic_branching.toml (docs/validation.md, "Dynamic branching"):
runs it at the cell sizes given (default 1, 0.5, 0.25 mm) and prints, per size, the notch tip's
initiation time, its speed just before the split (over the outer J domain's radius of path, as the
criterion measured it) and its largest speed over 2 mm of path before then, when and where the
tip splits and the half angle between the branches, where and when each branch reaches the
plate's edge, the branches' largest mirror mismatch (|y_left + y_right| at equal x), the energy
balance error, steps and wall time.
Usage: branching_study.py RUPTURE WORK_DIR [CELL_SIZES...] (BRANCH_END=SECONDS: another end time;
BRANCH_SET="KEY=VALUE ...": more --set options, e.g. nested levels round the path:
BRANCH_SET="grid.coarse_cell_size=1e-3 grid.refinement=nested grid.refine.path.level=1
grid.refine.path.min=[0.0,-0.014] grid.refine.path.max=[0.1,0.014]")"""
import json
import os
import subprocess
import sys

import numpy as np

rupture, work = sys.argv[1], sys.argv[2]
sizes = [float(v) for v in sys.argv[3:]] or [1e-3, 0.5e-3, 0.25e-3]
end = float(os.environ.get("BRANCH_END", "80e-6"))  # s
extra = [a for kv in os.environ.get("BRANCH_SET", "").split() for a in ("--set", kv)]
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "examples", "dynamic_branching.toml")
print("h_mm initiation_us speed_m_s peak_m_s split_us split_x_mm half_angle_deg "
      "left_end_mm left_us right_end_mm right_us mirror_mm energy_err steps wall_s")
for h in sizes:
    out = os.path.join(work, f"h_{h * 1e3:g}mm" + ("_set" if extra else ""))
    subprocess.run([rupture, "run", example, "-o", out, "--overwrite", "--quiet",
                    "--set", f"grid.cell_size={h!r}", "--set", f"interface.notch.segments={round(0.05 / h)}",
                    "--set", f"time.end={end!r}", *extra], check=True, stdout=subprocess.DEVNULL)
    r = json.load(open(os.path.join(out, "run.json")))
    d = np.genfromtxt(os.path.join(out, "crack_path_notch.csv"), delimiter=",", names=True)
    split = np.nonzero(d["end"] >= 2)[0]
    own = (d["tip"] < 2) & (d["end"] < 2)
    t, x = d["time"][own], d["x"][own]
    nan = float("nan")
    if len(split):
        ts, xs, half = d["time"][split[0]], d["x"][split[0]], d["angle"][split[0]]
        speed = d["speed"][split[0]]  # as the criterion measured it (crack_path's speed column)
        before = t <= ts
        tb, xb = t[before], x[before]
        # Largest speed over 2 mm of path before the split.
        peak = 0.0
        for i in range(len(xb)):
            k = np.nonzero(xb <= xb[i] - 2e-3 + 1e-12)[0]
            if len(k) and tb[i] > tb[k[-1]]:
                peak = max(peak, (xb[i] - xb[k[-1]]) / (tb[i] - tb[k[-1]]))
        ends = []
        for label in (2, 3):
            b = d[(d["tip"] == label) & (d["end"] < 2)]
            ends.append((b["y"][-1], b["time"][-1], b))
        lx, rx = ends[0][2]["x"], ends[1][2]["x"]
        common = np.linspace(max(lx.min(), rx.min()), min(lx.max(), rx.max()), 200)
        mirror = np.max(np.abs(np.interp(common, lx, ends[0][2]["y"]) + np.interp(common, rx, ends[1][2]["y"])))
        print(f"{h * 1e3:4g} {r['cracks.notch.initiation_time'] * 1e6:13.2f} {speed:9.0f} {peak:8.0f} {ts * 1e6:8.2f} "
              f"{xs * 1e3:10.2f} {half:14.2f} {ends[0][0] * 1e3:11.2f} {ends[0][1] * 1e6:7.2f} "
              f"{ends[1][0] * 1e3:12.2f} {ends[1][1] * 1e6:8.2f} {mirror * 1e3:9.3f} "
              f"{r['energy_balance_error']:10.4f} {r['steps']:5d} {r['wall_seconds']:6.1f}")
    else:
        print(f"{h * 1e3:4g} {r['cracks.notch.initiation_time'] * 1e6:13.2f} no split; grown "
              f"{r['cracks.notch.length'] * 1e3:.2f} mm, steps {r['steps']}, wall {r['wall_seconds']:.1f} s")
