#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# volpost inside ParaView: installs Debian 12's ParaView 5.11 with the development files its
# CMake package needs (about 200 packages), builds volpost with the ParaView plugin into build/
# and runs the plugin's tests (ctest -L paraview). Arguments go to ctest. The plugin ends in
# build/lib/volpost/paraview/VolpostParaView/VolpostParaView.so (docs/user/paraview.md).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  paraview paraview-dev                    # pvpython, pvbatch, pvserver and the CMake package
  libopenmpi-dev openmpi-bin               # mpirun; ParaView's package checks MPI's headers
  # Libraries ParaView's CMake package looks for and paraview-dev does not bring:
  libutfcpp-dev libdouble-conversion-dev liblz4-dev liblzma-dev libexpat1-dev libeigen3-dev
  libfreetype-dev libjpeg-dev libpng-dev libtiff-dev libxml2-dev libjsoncpp-dev libglew-dev
  libogg-dev libtheora-dev libhdf5-openmpi-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  echo "paraview: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi

scripts/setup.sh
cmake --preset default -DVOLPOST_PARAVIEW=ON >/dev/null
cmake --build --preset default
ctest --preset default -L paraview "$@"
