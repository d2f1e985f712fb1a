#!/bin/bash
# Lamb's problem resolution study (docs/faults.md): examples/lamb_2d.toml at 12.5, 10, 8 and 5 m
# (and 2.5 m with --fine: about an hour on 2 cores), each compared with the exact solution by
# scripts/lamb_compare.py. Usage: scripts/lamb_study.sh [OUT_DIR] [--fine]
# MASS=lumped runs the lumped mass instead of the example's averaged one (docs/theory.md §19).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
RUPTURE=${RUPTURE:-$ROOT/build/release/bin/rupture}
OUT=${1:-runs/lamb_study}
CELLS="12.5 10 8 5"
[[ "${2:-}" == "--fine" ]] && CELLS="$CELLS 2.5"
mkdir -p "$OUT"
for h in $CELLS; do
  start=$(date +%s.%N)
  "$RUPTURE" run "$ROOT/examples/lamb_2d.toml" --overwrite --quiet --set grid.cell_size=$h ${MASS:+--set solver.mass=\"$MASS\"} -o "$OUT/h$h" \
    > "$OUT/h$h.log" 2>&1
  wall=$(echo "$(date +%s.%N) - $start" | bc)
  echo "## h = $h m (wall $wall s)"
  /usr/bin/python3 "$ROOT/scripts/lamb_compare.py" "$OUT/h$h"
done
