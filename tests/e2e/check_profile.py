#!/usr/bin/python3
"""A tabulated rate-and-state profile ([interface.NAME.profile]) gives the taper's answer when
it tabulates the taper: TPV101-2D in small (examples/tpv101_2d.toml, 60 x 20 km, 200 m, to 8 s,
when the front has run into the velocity-strengthening ends) with its [interface.fault.taper]
and with that table replaced by a profile of a along x sampled from the taper's
B(r) = 0.5 [1 + tanh(w/(r - W - w) + w/(r - W))] every 5 m over W < |x| < W + w. Linear
interpolation at 5 m misses B by at most 5^2 max|B''| / 8 = 8.3e-6 (max|B''| = 2.65e-6 /m^2 for
w = 3 km, by finite differences), so a by 6.6e-8 (relative 8e-6 of a = 0.008): the station slips
differ by at most twice the linear response to that error: 2 x 8.3e-6 x the difference a run
without either (a = 0.008 everywhere, the taper's whole change undone) makes, relative to the
peak slip (the factor 2 for the response's nonlinearity).
Usage: check_profile.py RUPTURE WORK_DIR"""
import math
import os
import re
import subprocess
import sys

import numpy as np

rupture, work = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "..", "examples", "tpv101_2d.toml")
os.makedirs(work, exist_ok=True)
text = open(example).read()
W, w, a_in, a_out = 15000.0, 3000.0, 0.008, 0.016
assert re.search(r"^half_width = 15000.0$", text, re.M) and re.search(r"^width = 3000.0$", text, re.M)
# The taper's table: its header up to the next table's header.
untapered = re.sub(r"^\[interface\.fault\.taper\].*?(?=^\[)", "", text, flags=re.M | re.S)
assert "[interface.fault.taper]" not in untapered


def a_of(r):
    if r <= W:
        return a_in
    if r >= W + w:
        return a_out
    B = 0.5 * (1.0 + math.tanh(w / (r - W - w) + w / (r - W)))
    return a_out + (a_in - a_out) * B


xs = [-30000.0] + [-(W + w) + 5.0 * k for k in range(601)] + [W + 5.0 * k for k in range(601)] + [30000.0]
rows = ", ".join(f"[{x:.1f}, {a_of(abs(x)):.17g}]" for x in xs)
profiled = untapered + f'\n[interface.fault.profile]\nalong = "x"\na = [{rows}]\n'
cases = {"taper": text, "profile": profiled, "untapered": untapered}
small = ["--set", "time.end=8", "--set", "grid.cell_size=200", "--set", "interface.fault.segments=300",
         "--set", "grid.min=[-30000.0,-10000.0]", "--set", "grid.max=[30000.0,10000.0]",
         "--set", "bodies.north.max=[30000.0,10000.0]", "--set", "bodies.south.min=[-30000.0,-10000.0]"]
for name, body in cases.items():
    path = os.path.join(work, f"{name}.toml")
    open(path, "w").write(body)
    r = subprocess.run([rupture, "run", path, "-o", os.path.join(work, name), "--overwrite", "--quiet"] + small,
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAIL: {name} run exited {r.returncode}:\n{r.stderr}")

stations = sorted(f[:-4] for f in os.listdir(os.path.join(work, "taper", "stations")))
worst_profile = worst_untapered = 0.0
for st in stations:
    rec = {n: np.loadtxt(os.path.join(work, n, "stations", f"{st}.csv"), delimiter=",", skiprows=1) for n in cases}
    peak = np.abs(rec["taper"][:, 1]).max()
    dp = np.abs(rec["profile"][:, 1] - rec["taper"][:, 1]).max() / peak
    du = np.abs(rec["untapered"][:, 1] - rec["taper"][:, 1]).max() / peak
    print(f"{st}: slip {rec['taper'][-1, 1]:.4f} m (taper), {rec['profile'][-1, 1]:.4f} m (profile), "
          f"{rec['untapered'][-1, 1]:.4f} m (untapered); largest difference to the taper's "
          f"{dp:.2e} (profile), {du:.2e} (untapered) of the peak")
    worst_profile, worst_untapered = max(worst_profile, dp), max(worst_untapered, du)
print(f"largest: profile {worst_profile:.2e}, untapered {worst_untapered:.2e} of the peak slip")
r = np.linspace(W + 1e-3, W + w - 1e-3, 2000001)
B = 0.5 * (1.0 + np.tanh(w / (r - W - w) + w / (r - W)))
miss = 5.0 ** 2 * (np.abs(np.diff(B, 2)).max() / (r[1] - r[0]) ** 2) / 8.0  # of the taper's change
bound = 2.0 * miss * worst_untapered
print(f"interpolation error in B at most {miss:.2e}: bound {bound:.2e} of the peak slip")
assert worst_untapered > 1e-2, "the taper should matter at these stations"
assert worst_profile <= bound, "the tabulated taper should give the taper's answer"
print("profile checks passed")
