#!/bin/sh
# One rank's failure stops every rank (parallel/agreement.hpp, parallel/halo.hpp fail_in_step):
#   mpi_fault.sh MPIEXEC RANKS FAULT CODE DIR RUPTURE ARGS...
# runs `MPIEXEC -n RANKS RUPTURE ARGS... -o DIR` with RUPTURE_INJECT_FAULT=FAULT (SITE:RANK:STEP,
# core/fault_injection.hpp; "none" for a real failure set up by ARGS) and passes when every rank
# stopped within the time bound (a rank left waiting in a collective call would hang: `timeout`
# then gives 124), the exit code is CODE, the diagnosis is printed once ("error: ... (rank r)")
# and, for a run (not a resume), run.json says "failed".
mpiexec=$1 ranks=$2 fault=$3 code=$4 dir=$5
shift 5
err=$(mktemp)
if [ "$fault" = none ]; then unset RUPTURE_INJECT_FAULT; else export RUPTURE_INJECT_FAULT=$fault; fi
timeout 120 "$mpiexec" --oversubscribe -n "$ranks" "$@" >/dev/null 2>"$err"
rc=$?
cat "$err"
errors=$(grep -c '^error: .*(rank [0-9]*)' "$err")
rm -f "$err"
echo "exit=$rc errors_printed=$errors"
[ "$rc" -eq 124 ] && { echo "FAIL: a rank did not stop within 120 s"; exit 1; }
[ "$rc" -eq "$code" ] || { echo "FAIL: exit code $rc, expected $code"; exit 1; }
[ "$errors" -eq 1 ] || { echo "FAIL: the diagnosis was printed $errors times, expected once"; exit 1; }
if [ -f "$dir/run.json" ] && [ "$1" != resume ] && [ "$2" != resume ]; then
  grep -q '"status" *: *"failed"' "$dir/run.json" || { echo "FAIL: run.json does not say failed"; exit 1; }
fi
echo "PASS"
