#!/usr/bin/env bash
# TPV101-2D resolution study (docs/faults.md): examples/tpv101_2d.toml at 100, 50 and 25 m, one
# cohesive segment per cell, each against the uguca reference at 50 m and 25 m
# (scripts/tpv101_compare.py; the reference is tests/data/validation/tpv101-2d-uguca, a copy of
# ../shared/validation/tpv101-2d-uguca).
# Usage: scripts/tpv101_study.sh OUT_DIR [CELL_SIZES...]
#   (default 100 50 25; on 2 cores 100 m ~25 s, 50 m ~3.5 min, 25 m ~30 min)
set -euo pipefail
out=${1:?usage: tpv101_study.sh OUT_DIR [cell sizes]}
shift || true
sizes=${*:-100 50 25}
bin=${RUPTURE:-build/release/bin/rupture}
ref=tests/data/validation/tpv101-2d-uguca
mkdir -p "$out"
for h in $sizes; do
  seg=$(/usr/bin/python3 -c "print(int(round(60000 / $h)))")
  "$bin" run examples/tpv101_2d.toml -o "$out/h$h" --overwrite --quiet \
    --set grid.cell_size="$h" --set interface.fault.segments="$seg" > "$out/h$h.log"
  grep -E "^(particles|steps|wall_seconds)=" "$out/h$h.log" | tr '\n' ' '; echo " h=$h"
  for g in 50m 25m; do
    echo "h = $h m against the reference at $g:"
    /usr/bin/python3 scripts/tpv101_compare.py "$out/h$h" "$ref" "$g" --until 9 || true
  done
done
