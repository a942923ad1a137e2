#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds volpost into build/ (CMake preset "default").
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -f build/build.ninja ]; then  # a configure that failed half-way leaves a cache only
  cmake --preset default >/dev/null
fi
cmake --build --preset default
