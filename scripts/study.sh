#!/usr/bin/env bash
# Parameter studies of the reference problem (examples/rosakis1999.toml), cropped to
# x <= 75 mm, -60 <= y <= 40 mm (no reflection reaches the interface before about 30 us),
# each study one `rupture sweep` into runs/study/<study>/ (resumable: run it again to continue;
# -j from STUDY_JOBS, default 1), then a table of the crack figures from run.json.
# Grids are uniform (grid.coarse_cell_size = 0) unless stated.
#   scripts/study.sh grid  [H...]      V = 30 m/s to 19.2 us at each H (default 0.5, 0.25, 0.125 mm)
#   scripts/study.sh sweep [H [GRID [V...]]]
#                                      V = 5, 9.2, 9.5, 10, 20, 30 m/s (or the V given) to 30 us,
#                                      each stopping once its crack reaches the end of the weak
#                                      plane at 50 mm (time.stop_at_interface_end), so the
#                                      sustained speed is that of the running crack; at H
#                                      (default 0.125e-3) on GRID = uniform (default) or refined
#                                      (the example's graded grid with finest cell H)
#   scripts/study.sh map               the crack-speed map at 24 MPa on the paper's mesh policy: the
#                                      sweeps `sweep 62.5e-6 refined 5 6 7 8 9 9.2 9.5 10` and
#                                      `sweep 31.25e-6 refined 12 15 20 30 40 50 60` (resumed where
#                                      done), then one table (scripts/map_table.py)
#   scripts/study.sh refined H [full]  V = 30 m/s on the example's refined grid, finest H,
#                                      cropped (or the full plate with `full`)
#   scripts/study.sh safety H [S...]   V = 30 m/s to 19.2 us at uniform H for each
#                                      time.cohesive_safety S (default 0.125 0.25 0.5 0.7 0.9 1):
#                                      the answer must not depend on the step (docs/time_step.md)
#   scripts/study.sh transition H [KEY=V...]
#                                      V = 30 m/s to 11.6 us on the example's refined grid, finest H,
#                                      interface profiles every 0.05 us, crack samples every 0.01 us,
#                                      one run per KEY=V (none: the example), then scripts/transition.py:
#                                      separated stretches and shear-traction maxima ahead of the tip.
#                                      H below 31.25 um adds a level-7 box over x = 22-32 mm,
#                                      |y| <= 0.75 mm (the tip's path to 11.6 us) and narrows level 6
#   scripts/study.sh table DIR...      print the table for finished runs (DIR: run directories)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=./build/release/bin/rupture
crop=(--set grid.min=[0.0,-0.06] --set grid.max=[0.075,0.04] --set bodies.upper.max=[0.075,0.04]
      --set bodies.lower.min=[0.0,-0.06] --set bodies.lower.max=[0.075,0.0]
      --set interface.weak_plane.bonded_to=0.075 --set output.snapshot_interval=0
      --set output.interface_interval=0)
uniform=(--set grid.coarse_cell_size=0)

table() {
  /usr/bin/python3 - "$@" <<'PY'
import json, sys, csv
import numpy as np
print(f"{'run':<30}{'h (mm)':>8}{'V (m/s)':>9}{'t end':>7}{'steps':>7}{'particles':>11}{'wall (s)':>10}"
      f"{'init (us)':>10}{'jump (us)':>10}{'sust (m/s)':>11}{'/c_S':>6}{'last 4us':>9}{'tip@17.6':>10}"
      f"{'zone (mm)':>10}{'loaded':>8}{'E err':>10}  regime")
def us(t):  # a time in us, or "-" for never (-1)
    return f"{1e6*t:.3f}" if t >= 0 else "-"
for d in sys.argv[1:]:
    try:
        r = json.load(open(f"{d}/run.json"))
    except OSError:
        continue
    c = r["crack"]
    cs = next(iter(r["wave_speeds"].values()))["shear"]
    rows = list(csv.DictReader(open(f"{d}/crack_tip.csv")))
    t = np.array([float(x["time"]) for x in rows]); x = np.array([float(x["tip_x"]) for x in rows])
    tip = np.interp(17.6e-6, t, x) if t[-1] >= 17.6e-6 else float("nan")
    zone = np.array([float(x["cohesive_zone_length"]) for x in rows])
    z176 = np.interp(17.6e-6, t, zone) if t[-1] >= 17.6e-6 else float("nan")
    loaded = float("nan")
    if "traction_zone_length" in rows[0] and t[-1] >= 17.6e-6:
        loaded = np.interp(17.6e-6, t, np.array([float(x["traction_zone_length"]) for x in rows]))
    h = r["input"]["grid"]["cell_size"]; v = r["input"]["boundary"]["impact"]["velocity"]
    print(f"{d.rstrip('/').split('/')[-1]:<30}{1e3*h:>8.4g}{v:>9.3g}{1e6*r['simulated_time']:>7.2f}{r['steps']:>7}{r['particles']:>11}"
          f"{r['wall_seconds']:>10.1f}{us(c['initiation_time']):>10}{us(c['intersonic_time']):>10}"
          f"{c['sustained_speed']:>11.0f}{c['sustained_speed']/cs:>6.2f}{c.get('last_window_speed', float('nan')):>9.0f}"
          f"{1e3*tip:>10.2f}{1e3*z176:>10.2f}{1e3*loaded:>8.2f}"
          f"{r['energy_balance_error']:>10.2e}  {c['regime']}")
PY
}

# study DIR KEY V... -- SET...: one `rupture sweep` of KEY over the values, then the table.
study() {
  local dir=$1 key=$2; shift 2; local vs=()
  while [ "$1" != -- ]; do vs+=("$1"); shift; done; shift
  local IFS=,
  $bin sweep examples/rosakis1999.toml -o "$dir" --vary "$key=${vs[*]}" -j "${STUDY_JOBS:-1}" "$@" || true
  unset IFS
  table "$dir"/*/
}

case "${1:-}" in
  grid)
    shift; hs=("$@"); [ ${#hs[@]} -gt 0 ] || hs=(0.5e-3 0.25e-3 0.125e-3)
    study runs/study/grid grid.cell_size "${hs[@]}" -- "${crop[@]}" "${uniform[@]}" ;;
  sweep)
    h=${2:-0.125e-3}; kind=${3:-uniform}; shift $(( $# < 3 ? $# : 3 )); vs=("$@")
    [ ${#vs[@]} -gt 0 ] || vs=(5 9.2 9.5 10 20 30)
    case $kind in uniform) grid=("${uniform[@]}"); tag=;; refined) grid=(); tag=_refined;;
      *) echo "GRID must be uniform or refined, not $kind" >&2; exit 1;; esac
    study runs/study/sweep_h$h$tag boundary.impact.velocity "${vs[@]}" -- "${crop[@]}" \
      ${grid[@]+"${grid[@]}"} --set grid.cell_size=$h --set time.end=30e-6 \
      --set time.stop_at_interface_end=true --set output.mach_interval=1e-6 ;;
  refined)
    h=${2:?finest cell size}; d=runs/study/refined_h$h${3:+_$3}
    if [ "${3:-}" = full ]; then extra=(--set output.snapshot_interval=0 --set output.interface_interval=0)
    else extra=("${crop[@]}"); fi
    $bin run examples/rosakis1999.toml -o "$d" --overwrite --quiet "${extra[@]}" --set grid.cell_size=$h \
      | grep -E "^(particles|steps|wall_seconds|crack.sustained_speed|status)="
    table "$d" ;;
  safety)
    h=${2:?cell size}; shift 2; ss=("$@"); [ ${#ss[@]} -gt 0 ] || ss=(0.125 0.25 0.5 0.7 0.9 1.0)
    study runs/study/safety_h$h time.cohesive_safety "${ss[@]}" -- "${crop[@]}" "${uniform[@]}" \
      --set grid.cell_size=$h ;;
  map)
    "$0" sweep 62.5e-6 refined 5 6 7 8 9 9.2 9.5 10 >/dev/null
    "$0" sweep 31.25e-6 refined 12 15 20 30 40 50 60 >/dev/null
    /usr/bin/python3 scripts/map_table.py runs/study/sweep_h62.5e-6_refined runs/study/sweep_h31.25e-6_refined ;;
  transition)
    h=${2:?finest cell size}; shift 2; sets=("$@"); [ ${#sets[@]} -gt 0 ] || sets=(example)
    fine=()
    if /usr/bin/python3 -c "import sys; sys.exit(not float('$h') < 31.25e-6 * 0.99)"; then
      fine=(--set "grid.refine.level6.min=[0.021,-0.0015]" --set "grid.refine.level6.max=[0.035,0.0015]"
            --set "grid.refine.level7.min=[0.022,-0.00075]" --set "grid.refine.level7.max=[0.032,0.00075]"
            --set grid.refine.level7.level=7)
    fi
    dirs=()
    for kv in "${sets[@]}"; do
      d=runs/study/transition_h$h/${kv//[^A-Za-z0-9_.=-]/_}; dirs+=("$d")
      extra=(); [ "$kv" = example ] || extra=(--set "$kv")
      [ -f "$d/run.json" ] || $bin run examples/rosakis1999.toml -o "$d" --overwrite --quiet "${crop[@]}" \
        ${fine[@]+"${fine[@]}"} --set grid.cell_size=$h --set time.end=11.6e-6 \
        --set output.interface_interval=0.05e-6 --set output.crack_sample_interval=0.01e-6 \
        ${extra[@]+"${extra[@]}"} | grep -E "^(particles|steps|wall_seconds|status)=" || echo "$d: failed" >&2
    done
    /usr/bin/python3 scripts/transition.py "${dirs[@]}" ;;
  table) shift; table "$@" ;;
  *) sed -n 2,17p "$0"; exit 1 ;;
esac
