#!/usr/bin/env bash
# Bimaterial fault resolution study (docs/faults.md "Normal-stress regularization"):
# examples/bimaterial_fault_2d.toml at 200, 100 and 50 m (one segment per cell), with the
# example's regularization (slip form) and without it (normal_relaxation = "none"); then each
# set's station table (scripts/tpv205_table.py: the same stations) and how far consecutive
# resolutions lie apart (scripts/bimaterial_convergence.py).
# Usage: scripts/bimaterial_study.sh OUT_DIR [CELL_SIZES...]   (default 200 100 50; 50 m: ~5 min each)
set -euo pipefail
out=${1:?usage: bimaterial_study.sh OUT_DIR [cell sizes]}
shift || true
sizes=${*:-200 100 50}
bin=${RUPTURE:-build/release/bin/rupture}
case=examples/bimaterial_fault_2d.toml
for form in slip none; do
  mkdir -p "$out/$form"
  for h in $sizes; do
    seg=$(/usr/bin/python3 -c "print(int(round(40000 / $h)))")
    "$bin" run "$case" -o "$out/$form/h$h" --overwrite --quiet \
      --set grid.cell_size="$h" --set interface.fault.segments="$seg" \
      --set interface.fault.normal_relaxation="\"$form\"" > "$out/$form/h$h.log"
    grep -E "^(particles|steps|wall_seconds)=" "$out/$form/h$h.log" | tr '\n' ' '; echo " form=$form h=$h"
  done
  echo "## normal_relaxation = $form"
  /usr/bin/python3 scripts/tpv205_table.py $(for h in $sizes; do echo "$out/$form/h$h"; done)
done
/usr/bin/python3 scripts/bimaterial_convergence.py "$out" $sizes
