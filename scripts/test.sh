#!/usr/bin/env bash
# Installs dependencies, builds (Release) and runs every test with ctest but those labelled long
# (ctest --preset release -L long runs them).
# Set RUPTURE_SANITIZE=1 to also build and run the ASan+UBSan preset.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
ctest --preset release -LE long
if [ "${RUPTURE_SANITIZE:-0}" = "1" ]; then
  cmake --preset sanitize
  cmake --build --preset sanitize
  ASAN_OPTIONS=detect_leaks=0 ctest --preset sanitize -E 'e2e_' -LE 'benchmark|long|release_only'
fi
