#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian 12 packages volpost needs to build, run and test. Idempotent: says
# nothing and changes nothing when everything is there.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev
  libglm-dev libopenmesh-dev libepoxy-dev libegl-dev libgl-dev
  libegl-mesa0 libgl1-mesa-dri            # Mesa llvmpipe: OpenGL 4.5 with no GPU
  libpugixml-dev zlib1g-dev nlohmann-json3-dev libnetcdf-dev
  libcgal-dev libtet1.5-dev               # exact predicates; tetrahedralization templates
  libboost-dev                            # Gauss-Legendre nodes of the pre-integration table
  libkissfft-dev                          # the Hilbert transform of seismic attributes
  libmuparser-dev                         # the calculator's formulas
  libavformat-dev libavcodec-dev libswscale-dev libavutil-dev  # videos of animations
  libgtest-dev libbenchmark-dev
  xvfb xauth fonts-dejavu-core            # GUI tests on a virtual display; legend text
  clang-format                            # the format check of changed lines (.ci/run)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "setup: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
