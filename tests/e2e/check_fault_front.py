#!/usr/bin/python3
"""The rupture front of examples/tpv205_2d.toml (run.json cracks[0].front, cohesive/
rupture_front.hpp) at two resolutions:

  check_fault_front.py FINE COARSE      (200 m and 400 m cells, 200 segments of 200 m, to 6 s)

What the case fixes exactly: the nucleation patch is the overstressed stretch |x| <= 1.5 km
(81.6 MPa above the static strength 81.24 MPa; fault nodes every 200 m, so s = 18.6 to 21.4
km), the front leaves it on both sides at the same time (the problem is symmetric about x = 0
until the front meets the patches at -+7.5 km), and it stops at the strength barrier
(mu_s = 1e4 beyond |x| = 15 km: s = 5 and 35 km) on both sides by 6 s. What the resolution
study says: on the backward side (towards the 78 MPa patch, S = 0.22) the front turns
supershear at the same place at both resolutions, within two coarse cells (each run locates it
to a window start, one cell), and the forward side's median stays below c_S. The crack-tip
summary of the same run reads the patch breaking at once as its peak_speed; the front's peak
is a front's (at most c_D)."""
import json
import os
import sys

fine, coarse = sys.argv[1:3]
C_D, C_S = 6000.0, 3464.1


def front(d):
    with open(os.path.join(d, "run.json")) as f:
        r = json.load(f)
    c = r["cracks"][0]
    return c, c["front"], r["dt"]


ok = True


def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and cond


fronts = {}
for label, d in (("200 m", fine), ("400 m", coarse)):
    crack, f, dt = front(d)
    fronts[label] = f
    fw, bw = f["forward"], f["backward"]
    check(f["nucleation_overstressed"] and f["nucleation_begin_s"] == 18600.0 and f["nucleation_end_s"] == 21400.0,
          f"{label}: patch s = [{f['nucleation_begin_s']}, {f['nucleation_end_s']}] m, the overstressed |x| <= 1.5 km")
    check(abs(fw["leave_time"] - bw["leave_time"]) <= dt * (1 + 1e-9),
          f"{label}: leaves the patch at {fw['leave_time']:.4f} s forward, {bw['leave_time']:.4f} s backward (symmetric)")
    check(fw["reach_s"] == 35000.0 and bw["reach_s"] == 5000.0,
          f"{label}: reaches s = {bw['reach_s']} and {fw['reach_s']} m: the barriers at |x| = 15 km")
    check(fw["speed"] < C_S and fw["regime"] in ("sub-Rayleigh", "Rayleigh-to-shear"),
          f"{label}: forward median {fw['speed']:.0f} m/s, {fw['regime']}")
    check(bw["supershear_s"] > 0 and bw["regime"] == "intersonic",
          f"{label}: backward median {bw['speed']:.0f} m/s ({bw['regime']}), supershear from s = {bw['supershear_s']} m")
    check(0 < f["peak_speed"] <= C_D,
          f"{label}: front peak {f['peak_speed']:.0f} m/s <= c_D (the tip summary's peak_speed: {crack['peak_speed']:.0f} m/s)")
a, b = fronts["200 m"]["backward"]["supershear_s"], fronts["400 m"]["backward"]["supershear_s"]
check(abs(a - b) <= 800.0, f"backward supershear transition at s = {a} m (200 m) and {b} m (400 m): within 800 m")
sys.exit(0 if ok else 1)
