#!/usr/bin/env bash
# Installs dependencies, builds (Release) and runs every test with ctest but those labelled long
# (ctest --preset release -L long runs them).
# Set RUPTURE_SANITIZE=1 to also build and run the ASan+UBSan preset.
# Prints each phase's wall time (test.sh: PHASE N s), so that CI's half hour can be followed.
set -euo pipefail
cd "$(dirname "$0")/.."
phase() {  # phase NAME COMMAND...: runs it, then prints its wall time
  local name=$1 t=$SECONDS
  shift
  "$@"
  echo "test.sh: $name $((SECONDS - t)) s"
}
phase install-deps ./scripts/install-deps.sh
phase configure-release cmake --preset release
phase build-release cmake --build --preset release
phase ctest-release ctest --preset release -LE long
if [ "${RUPTURE_SANITIZE:-0}" = "1" ]; then
  phase configure-sanitize cmake --preset sanitize
  phase build-sanitize cmake --build --preset sanitize
  ASAN_OPTIONS=detect_leaks=0 phase ctest-sanitize ctest --preset sanitize -E 'e2e_' -LE 'benchmark|long|release_only'
fi
echo "test.sh: total $SECONDS s"
