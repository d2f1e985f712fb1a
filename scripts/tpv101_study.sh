#!/usr/bin/env bash
# TPV101-2D resolution study (docs/faults.md): examples/tpv101_2d.toml at 100, 50 and 25 m, one
# cohesive segment per cell, each against the uguca reference at 50 m and 25 m
# (scripts/tpv101_compare.py; the reference is tests/data/validation/tpv101-2d-uguca, a copy of
# ../shared/validation/tpv101-2d-uguca). With --nested: examples/tpv101_2d_nested.toml (nested
# levels, edges 30 km off the fault) at the finest cell sizes given.
# Usage: scripts/tpv101_study.sh OUT_DIR [--nested] [CELL_SIZES...]
#   (default 100 50 25; on 2 cores 100 m ~25 s, 50 m ~3.5 min, 25 m ~30 min;
#    nested: 50 m ~1 min, 25 m ~5 min)
set -euo pipefail
out=${1:?usage: tpv101_study.sh OUT_DIR [--nested] [cell sizes]}
shift || true
example=examples/tpv101_2d.toml
length=60000
if [[ ${1:-} == --nested ]]; then
  example=examples/tpv101_2d_nested.toml
  length=72000
  shift
fi
sizes=${*:-100 50 25}
bin=${RUPTURE:-build/release/bin/rupture}
ref=tests/data/validation/tpv101-2d-uguca
mkdir -p "$out"
for h in $sizes; do
  seg=$(/usr/bin/python3 -c "print(int(round($length / $h)))")
  "$bin" run "$example" -o "$out/h$h" --overwrite --quiet \
    --set grid.cell_size="$h" --set interface.fault.segments="$seg" > "$out/h$h.log"
  grep -E "^(particles|steps|wall_seconds)=" "$out/h$h.log" | tr '\n' ' '; echo " h=$h"
  for g in 50m 25m; do
    echo "h = $h m against the reference at $g:"
    /usr/bin/python3 scripts/tpv101_compare.py "$out/h$h" "$ref" "$g" --until 9 || true
  done
done
