#!/usr/bin/env bash
# TPV205-2D resolution study (docs/faults.md): examples/tpv205_2d.toml at 200, 100 and 50 m,
# one cohesive segment per cell, then the station table of each (scripts/tpv205_table.py).
# Usage: scripts/tpv205_study.sh OUT_DIR [CELL_SIZES...]   (default 200 100 50; 50 m: ~6 min on 2 cores)
# CASE=examples/tpv205_2d_benchmark_domain.toml FAULT_LENGTH=64000: the benchmark's domain.
set -euo pipefail
out=${1:?usage: tpv205_study.sh OUT_DIR [cell sizes]}
shift || true
sizes=${*:-200 100 50}
bin=${RUPTURE:-build/release/bin/rupture}
mkdir -p "$out"
case=${CASE:-examples/tpv205_2d.toml}
length=${FAULT_LENGTH:-40000}
for h in $sizes; do
  seg=$(/usr/bin/python3 -c "print(int(round($length / $h)))")
  "$bin" run "$case" -o "$out/h$h" --overwrite --quiet \
    --set grid.cell_size="$h" --set interface.fault.segments="$seg" > "$out/h$h.log"
  grep -E "^(particles|steps|wall_seconds)=" "$out/h$h.log" | tr '\n' ' '; echo " h=$h"
done
/usr/bin/python3 scripts/tpv205_table.py $(for h in $sizes; do echo "$out/h$h"; done)
