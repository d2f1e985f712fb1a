#!/usr/bin/env python3
"""A run with time.stop_at_interface_end ends when the crack reaches the end of the weak plane.

Usage: check_stop.py DIR END_TIME
The 30 m/s crack reaches 50 mm near 22.5 us, before END_TIME: the run must stop there with
stop_reason "crack_reached_interface_end", a tip within 2 cells of the end, and a sustained
speed (last 4 us before the stop) that is still the intersonic ~2300 m/s of the benchmark,
not an arrest.
"""
import json
import sys

d, end = sys.argv[1], float(sys.argv[2])
r = json.load(open(f"{d}/run.json"))
c = r["crack"]
ok = True


def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and cond


check(r["status"] == "completed", f"status {r['status']}")
check(r["stop_reason"] == "crack_reached_interface_end", f"stop_reason {r['stop_reason']}")
check(0 < c["end_reached_time"] <= r["simulated_time"] < end,
      f"stopped at {r['simulated_time']*1e6:.3f} us (end reached {c['end_reached_time']*1e6:.3f} us, "
      f"end_time {end*1e6:.1f} us)")
h = r["input"]["grid"]["cell_size"]
check(c["final_tip"] >= 0.05 - 2 * h - 1e-9, f"tip {c['final_tip']*1e3:.3f} mm")
check(abs(c["sustained_speed"] - 2300) <= 0.05 * 2300, f"sustained speed {c['sustained_speed']:.0f} m/s")
sys.exit(0 if ok else 1)
