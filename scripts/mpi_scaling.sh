#!/usr/bin/env bash
# Strong scaling of a distributed run on this machine (docs/parallel.md, "Measured scaling"):
# the reference problem cropped (75 x 100 mm, as benchmark_30ms) on a uniform grid, to END, with
# 1 process x 1 thread, 2 processes x 1 thread, and 1 process x 2 threads; prints each run's
# wall time, particle-updates per second, and the exchange figures of the 2-process run.
# With GRID = nested: the whole example on nested levels, each at its own time step (its
# fastest realization; SUBCYCLING=none for one step for all), finest cell CELL_SIZE.
# Usage: scripts/mpi_scaling.sh [CELL_SIZE] [END] [GRID]   (default 0.25e-3 m, 12e-6 s, uniform)
set -euo pipefail
cd "$(dirname "$0")/.."
h=${1:-0.25e-3}
end=${2:-12e-6}
grid=${3:-uniform}
bin=build/release/bin/rupture
case_args=(examples/rosakis1999.toml --overwrite --quiet
  --set grid.min=[0.0,-0.06] --set grid.max=[0.075,0.04] --set bodies.upper.max=[0.075,0.04]
  --set bodies.lower.min=[0.0,-0.06] --set bodies.lower.max=[0.075,0.0]
  --set interface.weak_plane.bonded_to=0.075 --set grid.coarse_cell_size=0
  --set grid.cell_size="$h" --set time.end="$end" --set output.snapshot_interval=0
  --set output.mach_interval=0 --set output.interface_interval=0)
if [ "$grid" = nested ]; then
  case_args=(examples/rosakis1999.toml --overwrite --quiet --set grid.refinement='"nested"'
    --set time.subcycling="\"${SUBCYCLING:-levels}\"" --set grid.cell_size="$h" --set time.end="$end"
    --set output.snapshot_interval=0 --set output.mach_interval=0 --set output.interface_interval=0)
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
lscpu | grep -E "Model name|^CPU\(s\)" || true
show() { grep -E "^(steps|wall_seconds|particle_updates_per_second|crack.initiation_time|ranks|exchange_bytes_per_rank_per_step|exchange_seconds|migrations)=" | tr '\n' ' '; echo; }
echo "== 1 process x 1 thread";  OMP_NUM_THREADS=1 $bin run "${case_args[@]}" -o /tmp/scaling_1x1 | show
echo "== 2 processes x 1 thread"; OMP_NUM_THREADS=1 mpirun -n 2 --bind-to core $bin run "${case_args[@]}" -o /tmp/scaling_2x1 | show
echo "== 1 process x 2 threads";  OMP_NUM_THREADS=2 $bin run "${case_args[@]}" -o /tmp/scaling_1x2 | show
