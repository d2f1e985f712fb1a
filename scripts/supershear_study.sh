#!/usr/bin/env bash
# Nucleated supershear (docs/faults.md): examples/supershear_2d.toml with a low seismic ratio
# (tau0 = 73 MPa, S = 0.82) and a high one (tau0 = 69.08 MPa, S = 2.0), then the front speed
# along the fault and the supershear transition distance of each (scripts/front_speed.py).
# Usage: scripts/supershear_study.sh OUT_DIR [cell size, m; default 100]
set -euo pipefail
out=${1:?usage: supershear_study.sh OUT_DIR [cell size]}
h=${2:-100}
bin=${RUPTURE:-build/release/bin/rupture}
seg=$(/usr/bin/python3 -c "print(int(round(40000 / $h)))")
for tau in 73e6 69.08e6; do
  "$bin" run examples/supershear_2d.toml -o "$out/tau$tau" --overwrite --quiet \
    --set grid.cell_size="$h" --set interface.fault.segments="$seg" \
    --set "interface.fault.initial_traction=[-120e6, $tau]" > "$out/tau$tau.log"
  echo "tau0 = $tau Pa:"
  /usr/bin/python3 scripts/front_speed.py "$out/tau$tau" 2>/dev/null | grep -E "transition|^ " | tail -40
done
