#!/usr/bin/env bash
# Bimaterial fault resolution study (docs/faults.md "Normal-stress regularization"):
# examples/bimaterial_fault_2d.toml at 200, 100 and 50 m (one segment per cell), with the
# example's regularization (slip form) and without it (normal_relaxation = "none"); then each
# set's station table (scripts/tpv205_table.py: the same stations) and how far consecutive
# resolutions lie apart (scripts/bimaterial_convergence.py).
# SCALES="0.8 0.2 0.1": also the slip form at these L (m) instead of the example's 0.4, at each
# cell size (OUT_DIR/L<value>/h<cell>), and how far each lies from the example's L at each cell;
# FORMS="" skips the runs with and without the example's regularization (already in OUT_DIR).
# Usage: scripts/bimaterial_study.sh OUT_DIR [CELL_SIZES...]   (default 200 100 50; 50 m: ~2 min each)
set -euo pipefail
out=${1:?usage: bimaterial_study.sh OUT_DIR [cell sizes]}
shift || true
sizes=${*:-200 100 50}
bin=${RUPTURE:-build/release/bin/rupture}
case=examples/bimaterial_fault_2d.toml
# run DIR H LABEL [--set ...]: the example at cell H into DIR/hH, one segment per cell.
run() {
  local dir=$1 h=$2 label=$3
  shift 3
  mkdir -p "$dir"
  local seg
  seg=$(/usr/bin/python3 -c "print(int(round(40000 / $h)))")
  "$bin" run "$case" -o "$dir/h$h" --overwrite --quiet \
    --set grid.cell_size="$h" --set interface.fault.segments="$seg" "$@" > "$dir/h$h.log"
  grep -E "^(particles|steps|wall_seconds)=" "$dir/h$h.log" | tr '\n' ' '; echo " $label h=$h"
}
for form in ${FORMS-slip none}; do
  for h in $sizes; do
    run "$out/$form" "$h" "form=$form" --set interface.fault.normal_relaxation="\"$form\""
  done
  echo "## normal_relaxation = $form"
  /usr/bin/python3 scripts/tpv205_table.py $(for h in $sizes; do echo "$out/$form/h$h"; done)
done
[ -n "${FORMS-slip none}" ] && /usr/bin/python3 scripts/bimaterial_convergence.py "$out" $sizes
for L in ${SCALES:-}; do
  for h in $sizes; do
    run "$out/L$L" "$h" "L=$L" --set interface.fault.normal_relaxation_slip="$L"
  done
done
if [ -n "${SCALES:-}" ]; then
  /usr/bin/python3 scripts/bimaterial_convergence.py "$out" $sizes --scales $SCALES
fi
