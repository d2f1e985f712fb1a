#!/usr/bin/env bash
# Grid and load study of examples/mode_I.toml (Freund's crack-face step, theory E18): for each
# cell size H and crack-face pressure S (Pa), a run into runs/mode_I/h<H>_s<S>, then a table of
# the initiation time (run.json crack.initiation_time) against Freund's t_F, when K_I(t) = K_c.
#   scripts/mode_I_study.sh [H...] [-- S...]    default H = 0.25e-3 0.125e-3 0.0625e-3, S = 5e6
# 0.0625 mm: ~1 min on 2 cores. Results: docs/validation.md.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=./build/release/bin/rupture
hs=() loads=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do hs+=("$1"); shift; done
[ $# -gt 0 ] && shift
loads=("$@")
[ ${#hs[@]} -eq 0 ] && hs=(0.25e-3 0.125e-3 0.0625e-3)
[ ${#loads[@]} -eq 0 ] && loads=(5e6)
dirs=()
for h in "${hs[@]}"; do
  for s in "${loads[@]}"; do
    d=runs/mode_I/h${h}_s${s}
    "$bin" run examples/mode_I.toml -o "$d" --overwrite --quiet --set grid.cell_size="$h" \
      --set interface.weak_plane.segments=2000 --set loads.upper_face.normal=-"$s" \
      --set loads.lower_face.normal=-"$s" --set output.snapshot_interval=0 \
      --set output.interface_interval=0.25e-6 > /dev/null
    dirs+=("$d")
  done
done
/usr/bin/python3 - "${dirs[@]}" <<'PY'
import json, math, sys
E, nu, rho, phi = 5.2e9, 0.34, 1246.0, math.e * 24e6 * 0.4e-6
cd = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho))
kc2 = E / (1 - nu * nu) * phi
print("| h (mm) | sigma* (MPa) | t_F (us) | initiation (us) | t_init / t_F | wall (s) |")
print("|---|---|---|---|---|---|")
for d in sys.argv[1:]:
    r = json.load(open(d + "/run.json"))
    h = float(d.split("_s")[0].split("/h")[1]); s = float(d.split("_s")[1])
    tf = math.pi * kc2 * (1 - nu) ** 2 / (4 * s * s * cd * (1 - 2 * nu))
    ti = r["crack"]["initiation_time"]
    print(f"| {h*1e3:g} | {s/1e6:g} | {tf*1e6:.3f} | {ti*1e6:.3f} | {ti/tf:.3f} | {r['wall_seconds']:.0f} |")
PY
