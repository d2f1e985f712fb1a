#!/usr/bin/env bash
# Installs rupture's build and test dependencies from Debian 12 (apt) only.
# Quick when everything is already present: apt is only called for missing packages.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libtomlplusplus-dev libcli11-dev libfmt-dev libspdlog-dev
  libhdf5-openmpi-dev libopenmpi-dev openmpi-bin
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-numpy python3-matplotlib python3-h5py python3-pytest
  python3-paraview xvfb xauth  # pvpython and a virtual display: the ParaView tests of particles.xdmf
  clang-14 libclang-rt-14-dev libomp-14-dev  # the fuzzers (scripts/fuzz.sh: libFuzzer and the
                                             # sanitizer runtimes, only recommended by clang; OpenMP)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
