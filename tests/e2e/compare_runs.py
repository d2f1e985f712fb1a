#!/usr/bin/python3
"""Compares the crack figures of two finished runs (refined vs uniform grid at the same
finest cell size, theory §5): initiation within 0.1 us, speed within 2 % over the same window, the
last 4 us of both runs (crack.last_window_speed; each run's steady phase is found in its own
history, and two runs' phases need not coincide)."""
import json
import sys

a, b = (json.load(open(f"{d}/run.json")) for d in sys.argv[1:3])
ca, cb = a["crack"], b["crack"]
d_init = abs(ca["initiation_time"] - cb["initiation_time"])
d_speed = abs(ca["last_window_speed"] - cb["last_window_speed"]) / abs(cb["last_window_speed"])
print(f"initiation {1e6 * ca['initiation_time']:.3f} vs {1e6 * cb['initiation_time']:.3f} us "
      f"(difference {1e6 * d_init:.3f} us, limit 0.1); speed over the last 4 us "
      f"{ca['last_window_speed']:.0f} vs {cb['last_window_speed']:.0f} m/s (difference {100 * d_speed:.2f} %, "
      f"limit 2 %; steady phases {ca['sustained_speed']:.0f} vs {cb['sustained_speed']:.0f}); "
      f"particles {a['particles']} vs {b['particles']}, wall {a['wall_seconds']:.0f} vs "
      f"{b['wall_seconds']:.0f} s")
ok = ca["initiated"] and cb["initiated"] and d_init <= 0.1e-6 and d_speed <= 0.02
sys.exit(0 if ok else 1)
