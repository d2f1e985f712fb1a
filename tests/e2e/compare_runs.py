#!/usr/bin/python3
"""Compares the crack figures of two finished runs (refined vs uniform grid at the same
finest cell size, SPEC §5): initiation within 0.1 us, sustained speed within 2 %."""
import json
import sys

a, b = (json.load(open(f"{d}/run.json")) for d in sys.argv[1:3])
ca, cb = a["crack"], b["crack"]
d_init = abs(ca["initiation_time"] - cb["initiation_time"])
d_speed = abs(ca["sustained_speed"] - cb["sustained_speed"]) / abs(cb["sustained_speed"])
print(f"initiation {1e6 * ca['initiation_time']:.3f} vs {1e6 * cb['initiation_time']:.3f} us "
      f"(difference {1e6 * d_init:.3f} us, limit 0.1); sustained speed {ca['sustained_speed']:.0f} "
      f"vs {cb['sustained_speed']:.0f} m/s (difference {100 * d_speed:.2f} %, limit 2 %); "
      f"particles {a['particles']} vs {b['particles']}, wall {a['wall_seconds']:.0f} vs "
      f"{b['wall_seconds']:.0f} s")
ok = ca["initiated"] and cb["initiated"] and d_init <= 0.1e-6 and d_speed <= 0.02
sys.exit(0 if ok else 1)
