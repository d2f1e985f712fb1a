#!/usr/bin/python3
"""Crack growth that could fail if the physics or the geometry were wrong (docs/fracture.md,
"Growth"): examples/crack_growth_disc.toml, an inclined centre crack cut into a pre-stressed disc,
whose tips kink and curve by the maximum hoop stress criterion.
  - Rotation: the whole problem (disc, uniform stress, crack) turned by 30 degrees about the
    disc's centre must give the turned path. The lattice is not turned (particles and grid stay
    axis-aligned), so this tests that nothing in the growth (the tip frames, the split that
    follows, the ties) depends on the grid's axes. Every vertex of each tip's path, turned back,
    lies within one cell of the unturned path, and the grown lengths agree within 2 cells.
  - Half-turn symmetry: the problem is symmetric under a half turn about the crack's centre, so
    the two tips' paths map onto each other within one cell.
  - Path convergence: at h and h / 2 (the J domains and the growth step are in cells, so they
    shrink with h) the paths lie within h of each other over their common length.
Usage: check_crack_growth.py RUPTURE WORK_DIR"""
import json
import math
import os
import subprocess
import sys

import numpy as np

rupture, work = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "..", "examples", "crack_growth_disc.toml")
os.makedirs(work, exist_ok=True)
sigma, a, beta, y0 = 10e6, 0.01, math.radians(30.0), 1e-4
failures = []


def turn(p, phi):
    c, s = math.cos(phi), math.sin(phi)
    return np.array([c * p[0] - s * p[1], s * p[0] + c * p[1]])


def run(name, phi, h):
    ends = [turn((-a * math.cos(beta), y0 - a * math.sin(beta)), phi),
            turn((a * math.cos(beta), y0 + a * math.sin(beta)), phi)]
    c, s = math.cos(phi), math.sin(phi)
    stress = [sigma * s * s, sigma * c * c, -sigma * s * c]  # sigma n n, n = (-sin phi, cos phi)
    out = os.path.join(work, name)
    pts = f"[[{ends[0][0]!r}, {ends[0][1]!r}], [{ends[1][0]!r}, {ends[1][1]!r}]]"
    subprocess.run([rupture, "run", example, "-o", out, "--overwrite", "--quiet",
                    "--set", f"interface.crack.points={pts}",
                    "--set", f"bodies.disc.stress=[{stress[0]!r}, {stress[1]!r}, {stress[2]!r}]",
                    "--set", f"grid.cell_size={h!r}"], check=True, stdout=subprocess.DEVNULL)
    d = np.genfromtxt(os.path.join(out, "crack_path_crack.csv"), delimiter=",", names=True)
    paths = []
    for end in (0, 1):
        rows = d[d["end"] == end]
        vertices = [ends[end]] + [np.array([x, y]) for x, y in zip(rows["x"], rows["y"])]
        paths.append(np.array([turn(v, -phi) for v in vertices]))  # in the unturned frame
    record = json.load(open(os.path.join(out, "run.json")))
    return paths, record


def distance_to_polyline(p, line):
    best = math.inf
    for q0, q1 in zip(line[:-1], line[1:]):
        d = q1 - q0
        t = np.clip(np.dot(p - q0, d) / max(np.dot(d, d), 1e-300), 0.0, 1.0)
        best = min(best, np.linalg.norm(p - (q0 + t * d)))
    return best


def arc(line):
    return np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(line, axis=0), axis=1))])


def deviation(p, q):
    """Largest distance from either path's vertices to the other, over their common length."""
    common = min(arc(p)[-1], arc(q)[-1])
    worst = 0.0
    for u, v in ((p, q), (q, p)):
        for point, s in zip(u, arc(u)):
            if s <= common:
                worst = max(worst, distance_to_polyline(point, v))
    return worst, common


h = 1e-3
base, rec = run("base", 0.0, h)
turned, rec_t = run("turned_30", math.radians(30.0), h)
fine, rec_f = run("fine", 0.0, h / 2)
print(f"base: initiation {rec['cracks.crack.initiation_time'] * 1e6:.3f} us, initial angle "
      f"{rec['cracks.crack.initial_angle']:.2f} deg, grown {rec['cracks.crack.length'] * 1e3:.2f} mm")
print(f"turned 30: initiation {rec_t['cracks.crack.initiation_time'] * 1e6:.3f} us, initial angle "
      f"{rec_t['cracks.crack.initial_angle']:.2f} deg, grown {rec_t['cracks.crack.length'] * 1e3:.2f} mm")
print(f"h/2: initiation {rec_f['cracks.crack.initiation_time'] * 1e6:.3f} us, initial angle "
      f"{rec_f['cracks.crack.initial_angle']:.2f} deg, grown {rec_f['cracks.crack.length'] * 1e3:.2f} mm")
if not rec["cracks.crack.length"] >= 4 * h:
    failures.append(f"the base crack grew only {rec['cracks.crack.length']:.3g} m (the test needs growth)")
for end in (0, 1):
    dev, common = deviation(base[end], turned[end])
    print(f"tip {end}: turned path vs base {dev * 1e3:.3f} mm over {common * 1e3:.2f} mm (bound {h * 1e3:.1f})")
    if dev > h:
        failures.append(f"tip {end}: the turned path lies {dev:.3g} m from the base path (bound {h} m)")
    dev, common = deviation(base[end], fine[end])
    print(f"tip {end}: h/2 path vs h {dev * 1e3:.3f} mm over {common * 1e3:.2f} mm (bound {h * 1e3:.1f})")
    if dev > h:
        failures.append(f"tip {end}: the paths at h and h/2 lie {dev:.3g} m apart (bound {h} m)")
lengths = abs(rec["cracks.crack.length"] - rec_t["cracks.crack.length"])
print(f"grown length, turned - base: {lengths * 1e3:.3f} mm (bound {2 * h * 1e3:.1f})")
if lengths > 2 * h:
    failures.append(f"grown lengths differ by {lengths:.3g} m between the turned and base problems (bound {2 * h} m)")
# The half turn about the crack's centre (0, y0) maps tip 1's path onto tip 0's.
centre = np.array([0.0, y0])
mirrored = np.array([2 * centre - v for v in base[1]])
dev, common = deviation(base[0], mirrored)
print(f"half-turn symmetry: tip 1 turned vs tip 0 {dev * 1e3:.3f} mm over {common * 1e3:.2f} mm (bound {h * 1e3:.1f})")
if dev > h:
    failures.append(f"the two tips' paths differ by {dev:.3g} m under the half turn (bound {h} m)")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("crack growth: rotation, symmetry and path convergence hold")
