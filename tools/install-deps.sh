#!/usr/bin/env bash
# Installs the Debian 12 packages IMPACT-3D needs to build, run and test, if any is missing.
set -euo pipefail
PKGS=(g++ cmake make pkg-config libeigen3-dev zlib1g-dev libgtest-dev libgmock-dev libbenchmark-dev
      libpng-dev libfreetype-dev fonts-dejavu-core libosmesa6-dev libgl-dev
      python3 python3-vtk9 python3-numpy
      clang libclang-rt-14-dev libomp-dev  # the fuzz targets (tools/fuzz.sh): clang, libFuzzer, OpenMP
      libopenmpi-dev openmpi-bin libmetis-dev)  # distributed runs (docs/cluster.md): MPI, METIS
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "installing: ${missing[*]}"
  $SUDO apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi
