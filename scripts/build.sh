#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds volpost into build/ (CMake preset "default").
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -f build/CMakeCache.txt ]; then
  cmake --preset default >/dev/null
fi
cmake --build --preset default
