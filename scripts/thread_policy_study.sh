#!/usr/bin/env bash
# How the OpenMP threads' wait at a barrier costs on an idle and on a busy machine: one case run
# with 1 thread and with 2 under each wait setting, alone and beside one busy process (a shell
# loop on one core, as a second run or a build would be). Prints the wall time of each run.
#
#   scripts/thread_policy_study.sh RUPTURE CASE [--set K=V ...]
#
# The settings are those of libgomp (read when the program starts): OMP_WAIT_POLICY=active (spin
# until the work comes), passive (sleep at once), and GOMP_SPINCOUNT=N (spin N times, then sleep;
# libgomp's default without OMP_WAIT_POLICY is 300000). "auto" is rupture's default,
# solver.threads = 0: the count chosen from the step times (src/run/thread_tuner.hpp); the others
# fix solver.threads, which turns that off. Results: docs/performance.md, "Threads on a busy machine".
set -euo pipefail
exe=$1 case=$2
shift 2
out=$(mktemp -d)
trap 'rm -rf "$out"; [ -n "${busy:-}" ] && kill "$busy" 2>/dev/null || true' EXIT
run() {  # run LABEL THREADS ENV...: prints LABEL and the wall seconds
  local label=$1 threads=$2
  shift 2
  local t0 t1
  t0=$(date +%s.%N)
  env "$@" "$exe" run "$case" "${extra[@]}" --set "solver.threads=$threads" \
    -o "$out/run" --overwrite --quiet >/dev/null
  t1=$(date +%s.%N)
  printf '%-34s %8.2f s\n' "$label" "$(echo "$t1 - $t0" | bc -l)"
}
extra=("$@")
for load in idle busy; do
  busy=""
  if [ "$load" = busy ]; then
    ( while :; do :; done ) &
    busy=$!
  fi
  echo "# $load machine"
  run "1 thread" 1 -u GOMP_SPINCOUNT OMP_WAIT_POLICY=passive
  run "2 threads, libgomp default" 2 -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT
  run "2 threads, OMP_WAIT_POLICY=active" 2 -u GOMP_SPINCOUNT OMP_WAIT_POLICY=active
  run "2 threads, OMP_WAIT_POLICY=passive" 2 -u GOMP_SPINCOUNT OMP_WAIT_POLICY=passive
  for n in 10000 1000; do
    run "2 threads, GOMP_SPINCOUNT=$n" 2 -u OMP_WAIT_POLICY GOMP_SPINCOUNT=$n
  done
  run "auto (2 cores, libgomp default)" 0 -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT
  [ -n "$busy" ] && kill "$busy" && wait "$busy" 2>/dev/null || true
  busy=""
done
