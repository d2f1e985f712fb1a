#!/usr/bin/env bash
# Installs dependencies, builds (Release) and runs the default case into runs/default.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release
cmake --build --preset release --target rupture
case_file=${1:-examples/rosakis1999.toml}
./build/release/bin/rupture run "$case_file" -o runs/default --overwrite
./build/release/bin/rupture plot runs/default
echo "results: runs/default (run.json, history.csv, crack_tip.csv, particles.xdmf for ParaView)"
echo "figures: runs/default/figures (crack_tip.png, tau_max_fringes.png, cohesive_profiles.png)"
