#!/usr/bin/python3
"""The cropped reference problem (traction impact) rotated by several angles about the notch mouth:
how far the rotated crack's initiation, speed and energy balance move from the unrotated run's on
the same grid (issue "Any geometry", docs/validation.md "Rotation by 30 degrees").

Each angle's case is examples/inclined_weak_plane.toml with the plate (x <= 70 mm,
-55 <= y <= 30 mm), the weak plane (25-50 mm, bonded to 70 mm) and the loaded edge strip
(y in [-50, 0] mm on x = 0) rotated by that angle; the grid is the rotated plate's bounding box
plus one cell, its lines through the notch mouth. Angle 0 is the reference of the gaps. A square
grid looks the same at 90 - a as at a, mirrored; the problem is not mirror-symmetric (30 mm of
plate above the plane, 55 mm below), so 60 degrees is close to 30 degrees but not equal.

Usage: rotation_study.py OUT [--angles 0 15 30 40 44 45 60] [--cell-size 0.5e-3] [--shift X]
                          [--rupture BIN]
Writes OUT/a<angle>.toml, runs OUT/a<angle>/ (kept when run.json exists), prints a table.
The speeds are least-squares slopes of the tip's arc length over fixed windows (the last 4 us,
as tests/e2e/check_inclined.py, and 11.5-19.2 us), with their standard errors.
"""
import argparse
import math
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import rupture  # noqa: E402  (the package's readers: one reader per file, python/rupture)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UPPER = [(0, 0), (0.07, 0), (0.07, 0.03), (0, 0.03)]  # m, unrotated
LOWER = [(0, -0.055), (0.07, -0.055), (0.07, 0), (0, 0)]


def rotated_case(angle_deg, h, shift=0.0):
    th = math.radians(angle_deg)
    c, s = math.cos(th), math.sin(th)

    def rot(x, y):
        return (x * c - y * s + shift, x * s + y * c)

    def pt(x, y):
        a, b = rot(x, y)
        return f"[{a:.12f}, {b:.12f}]"

    text = open(os.path.join(ROOT, "examples/inclined_weak_plane.toml")).read()
    corners = [rot(*p) for p in UPPER + LOWER]
    lo = [math.floor(min(p[d] for p in corners) / h) * h - h for d in (0, 1)]
    hi = [math.ceil(max(p[d] for p in corners) / h) * h + h for d in (0, 1)]
    subs = [
        (r"^min = \[.*?\]$", f"min = [{lo[0]:.6f}, {lo[1]:.6f}]"),
        (r"^max = \[.*?\]$", f"max = [{hi[0]:.6f}, {hi[1]:.6f}]"),
        (r"^cell_size = .*$", f"cell_size = {h!r}"),
        (r"^title = .*$", f'title = "reference problem rotated by {angle_deg:g} degrees"'),
        (r"^points = .*$", f"points = [{pt(0.025, 0)}, {pt(0.05, 0)}]"),
        (r"^bonded_points = .*$", f"bonded_points = [{pt(0.05, 0)}, {pt(0.07, 0)}]"),
        (r"^from = .*$", f"from = {pt(0, -0.05)}"),
        (r"^to = .*$", f"to = {pt(0, 0)}"),
    ]
    for pattern, repl in subs:
        text, n = re.subn(pattern, repl, text, count=1, flags=re.M)
        assert n == 1, pattern
    verts = iter([", ".join(pt(*p) for p in UPPER), ", ".join(pt(*p) for p in LOWER)])
    text, n = re.subn(r"^vertices = .*$", lambda m: f"vertices = [{next(verts)}]", text, flags=re.M)
    assert n == 2
    return f"# rotated by {angle_deg} degrees (scripts/rotation_study.py)\n" + text


def slope(t, s, t0, t1):
    m = (t >= t0 - 1e-12) & (t <= t1 + 1e-12)
    p = np.polyfit(t[m], s[m], 1)
    r = s[m] - np.polyval(p, t[m])
    se = math.sqrt((r @ r) / (m.sum() - 2) / ((t[m] - t[m].mean()) ** 2).sum())
    return p[0], se


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--angles", type=float, nargs="+", default=[0, 15, 30, 40, 44, 45, 60])
    ap.add_argument("--cell-size", type=float, default=0.5e-3)
    ap.add_argument("--shift", type=float, default=0.0,
                    help="move the rotated problem along x by this much (m): a quarter cell keeps a "
                         "45-degree interface off the particle centres")
    ap.add_argument("--rupture", default=os.path.join(ROOT, "build/release/bin/rupture"))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    angles = sorted(set([0.0] + a.angles))
    rows = {}
    for ang in angles:
        name = f"a{ang:g}"
        case = os.path.join(a.out, name + ".toml")
        run = os.path.join(a.out, name)
        open(case, "w").write(rotated_case(ang, a.cell_size, a.shift))
        if not os.path.exists(os.path.join(run, "run.json")):
            subprocess.run([a.rupture, "run", case, "-o", run, "--overwrite", "--quiet"], check=True,
                           stdout=subprocess.DEVNULL)
        opened = rupture.open_run(run)
        r = opened.record
        tip = opened.crack_tip()
        t, s = tip["time"], tip["tip_s"]
        end = t[-1]
        rows[ang] = dict(init=r["crack"]["initiation_time"], last=slope(t, s, end - 4e-6, end),
                         whole=slope(t, s, 11.5e-6, end), energy=r["energy_balance_error"],
                         particles=r["particles"], wall=r["wall_seconds"])
    ref = rows[0.0]
    print(f"h = {a.cell_size * 1e3:g} mm; gaps against 0 degrees")
    print("| angle (deg) | particles | initiation (us) | d init (us) | speed, last 4 us (m/s) | gap |"
          " speed, 11.5 us-end (m/s) | gap | energy error | wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for ang, r in rows.items():
        g1 = 100 * (r["last"][0] / ref["last"][0] - 1)
        g2 = 100 * (r["whole"][0] / ref["whole"][0] - 1)
        print(f"| {ang:g} | {r['particles']} | {r['init'] * 1e6:.3f} | {(r['init'] - ref['init']) * 1e6:+.3f} | "
              f"{r['last'][0]:.1f} +- {r['last'][1]:.1f} | {g1:+.2f} % | {r['whole'][0]:.1f} +- {r['whole'][1]:.1f} | "
              f"{g2:+.2f} % | {100 * r['energy']:.2f} % | {r['wall']:.1f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
