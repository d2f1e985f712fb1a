#!/usr/bin/python3
"""The shear Mach angle of the 30 m/s reference problem (theory E12, §6: about 33 degrees).

Usage: check_mach.py RUN_DIR

Checks on run.json (crack.*) and mach_angle.csv, written with output.mach_interval:
- readings on both sides in the steady phase (at least 3);
- the median angle within 1.5 degrees of the paper's 33 (read from fringe photographs);
- the two sides within 1.5 degrees of each other: both are Homalite, and a Mach front's angle
  depends only on the speed and the material's c_S (symmetry of E12);
- the speed the angle implies, c_S / sin(beta), within 3 % of the E11 steady-phase speed (an
  independent measurement of the same speed: 1 degree at 33 degrees is 2.7 % in speed).
"""
import json
import sys

run = json.load(open(f"{sys.argv[1]}/run.json"))
k = run["crack"]
ok = True


def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and bool(cond)


check(k["mach_readings"] >= 3, f"{k['mach_readings']} readings in the steady phase "
      f"({k['steady_begin'] * 1e6:.2f}-{k['steady_end'] * 1e6:.2f} us)")
check(abs(k["mach_angle"] - 33.0) <= 1.5, f"Mach angle {k['mach_angle']:.2f} deg (spread "
      f"{k['mach_angle_spread']:.2f}) against the paper's 33 deg (limit 1.5)")
check(k["mach_angle_left"] > 0 and k["mach_angle_right"] > 0 and
      abs(k["mach_angle_left"] - k["mach_angle_right"]) <= 1.5,
      f"upper side {k['mach_angle_left']:.2f} deg, lower side {k['mach_angle_right']:.2f} deg (limit 1.5 apart)")
d = abs(k["mach_speed"] - k["sustained_speed"]) / k["sustained_speed"]
check(d <= 0.03, f"implied speed {k['mach_speed']:.1f} m/s against the E11 steady speed "
      f"{k['sustained_speed']:.1f} m/s ({100 * d:.2f} %, limit 3 %)")
sys.exit(0 if ok else 1)
