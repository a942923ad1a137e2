#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Sets up, builds and opens volpost on the bundled example (a wheel of hexahedra, wedges,
# pyramids and tetrahedra, colored by von Mises stress). With no display, renders the
# same view headless to a PNG and prints its path.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
model=resources/examples/wheel_mixed.vtu
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec build/bin/volpost "$model" --field S.mises
fi
echo "No display: rendering headless instead."
build/bin/volpost render "$model" --field S.mises --camera "iso,az=20" --size 1024x768 -o build/demo.png
