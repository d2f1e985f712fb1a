#!/usr/bin/env bash
# Writes tests/ctest_costs/{release,sanitize}.txt from the costs ctest measured in
# build/{release,sanitize} (Testing/Temporary/CTestCostData.txt): the seed a fresh build's ctest
# schedules by, longest first (tests/CMakeLists.txt). Run after a full ctest of both presets on a
# 2-core machine; the figures only order the tests, nothing asserts them.
set -euo pipefail
cd "$(dirname "$0")/.."
for preset in release sanitize; do
  src=build/$preset/Testing/Temporary/CTestCostData.txt
  [ -f "$src" ] || { echo "ctest_costs.sh: $src is missing (run ctest --preset $preset first)" >&2; exit 1; }
  # name runs cost: keep the name and the cost, one run each; drop the failed-test list after ---.
  awk '$1 == "---" {exit} NF == 3 {printf "%s 1 %.1f\n", $1, $3}' "$src" | sort > tests/ctest_costs/$preset.txt
  echo "tests/ctest_costs/$preset.txt: $(wc -l < tests/ctest_costs/$preset.txt) tests"
done
