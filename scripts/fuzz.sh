#!/usr/bin/env bash
# Builds the libFuzzer harnesses (cmake --preset fuzz: clang 14, ASan + UBSan; fuzz/README.md),
# runs every saved regression input and seed through them, then fuzzes both harnesses side by
# side (one core each) for RUPTURE_FUZZ_SECONDS seconds (default 45) from their seeds. A crash,
# undefined behaviour or an exception a harness does not expect stops that harness: its input
# is left in build/fuzz/crashes/TARGET/ (or RUPTURE_FUZZ_BUILD/fuzz/crashes/TARGET/) and the script fails. Prints each phase's wall time and
# libFuzzer's figures (executions, cov, ft).
# RUPTURE_FUZZ_BUILD=build/sanitize uses the harnesses the sanitize preset built (CI: the
# library built once for the tests and the fuzzers; only the readers' sources carry coverage
# there, src/CMakeLists.txt) instead of building the fuzz preset.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${RUPTURE_FUZZ_SECONDS:-45}
start=$SECONDS
build=${RUPTURE_FUZZ_BUILD:-build/fuzz}
if [ -z "${RUPTURE_FUZZ_BUILD:-}" ]; then
  cmake --preset fuzz > /dev/null
  cmake --build --preset fuzz > build/fuzz-build.log 2>&1 || { tail -50 build/fuzz-build.log; exit 1; }
  echo "fuzz: build $((SECONDS - start)) s"
else
  for target in checkpoint case_toml; do
    [ -x "$build/bin/fuzz_$target" ] || {
      echo "fuzz: RUPTURE_FUZZ_BUILD=$build has no bin/fuzz_$target (configure it with RUPTURE_FUZZ=ON and build it)" >&2
      exit 1
    }
  done
  echo "fuzz: the harnesses of $build"
fi
out=build/fuzz  # logs, corpus, crashes
[ -z "${RUPTURE_FUZZ_BUILD:-}" ] || out=$build/fuzz
mkdir -p "$out"
export OMP_NUM_THREADS=1 ASAN_OPTIONS=detect_leaks=0
# Halt on every UBSan report but the known findings not fixed yet (fuzz/found/README.md).
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions=$PWD/fuzz/found/ubsan.supp
t=$SECONDS
ctest --test-dir "$build" -L fuzz --output-on-failure > "$out/regressions.log" 2>&1 ||
  { cat "$out/regressions.log"; exit 1; }
echo "fuzz: regression inputs $((SECONDS - t)) s"
t=$SECONDS
for target in checkpoint case_toml; do
  work=$out/corpus/$target crashes=$out/crashes/$target
  mkdir -p "$work" "$crashes"
  seeds=(fuzz/corpus/checkpoint) limit=()
  if [ "$target" = case_toml ]; then
    seeds=(examples tests/inputs)
    # Inputs up to 64 KiB: deep nesting and long dotted keys are refused before the parser
    # (input/text_limits.hpp), and longer ones only slow the run.
    limit=(-max_len=65536)
  fi
  "$build/bin/fuzz_$target" -max_total_time="$seconds" "${limit[@]}" -detect_leaks=0 -print_final_stats=1 \
    -artifact_prefix="$crashes/" "$work" "${seeds[@]}" > "$out/$target.log" 2>&1 &
done
wait || true
status=0
for target in checkpoint case_toml; do
  grep -E "^#[0-9]+[[:space:]]+(INITED|DONE)|^stat::(number_of_executed_units|average_exec_per_sec)" "$out/$target.log" |
    sed "s/^/fuzz_$target: /"
  if compgen -G "$out/crashes/$target/*" > /dev/null; then
    grep -E "runtime error|ERROR: AddressSanitizer|ERROR: libFuzzer|SUMMARY|^    #[0-9]+ " "$out/$target.log" | head -30 >&2
    echo "fuzz: fuzz_$target found inputs that crash it: $out/crashes/$target (log: $out/$target.log)" >&2
    status=1
  fi
done
echo "fuzz: runs $((SECONDS - t)) s, total $((SECONDS - start)) s"
exit $status
