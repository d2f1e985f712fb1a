#!/usr/bin/python3
"""Runs `rupture plot DIR` and checks the figures: every PNG exists, is a PNG, has the size of
a real figure, was reported by the command, and no temporary file is left behind."""
import os
import struct
import subprocess
import sys

rupture, run_dir = sys.argv[1], sys.argv[2]
out = subprocess.run([rupture, "plot", run_dir], capture_output=True, text=True)
print(out.stdout, out.stderr)
if out.returncode != 0:
    sys.exit(f"rupture plot exited with {out.returncode}")
fig_dir = os.path.join(run_dir, "figures")
for name in ["crack_tip.png", "tau_max_fringes.png", "cohesive_profiles.png"]:
    path = os.path.join(fig_dir, name)
    if not os.path.isfile(path):
        sys.exit(f"missing figure {path}")
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path} is not a PNG")
    width, height = struct.unpack(">II", head[16:24])
    print(f"{name}: {width} x {height} px, {os.path.getsize(path)} bytes")
    if width < 400 or height < 300:
        sys.exit(f"{path} is too small to be a figure: {width} x {height}")
    if f"figure={path}" not in out.stdout:
        sys.exit(f"rupture plot did not report {path}")
leftovers = [f for f in os.listdir(fig_dir) if ".tmp" in f]
if leftovers:
    sys.exit(f"temporary files left behind: {leftovers}")
print("ok")
