#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# ParaView's window (Qt 5) loads the plugin, opens FILE through it and shows CELLS cells.
# Usage: in_the_window.sh PARAVIEW PLUGIN FILE READER CELLS
set -euo pipefail
result=$(mktemp)
trap 'rm -f "$result"' EXIT
VOLPOST_PV_PLUGIN=$2 VOLPOST_PV_FILE=$3 VOLPOST_PV_RESULT=$result \
  "$1" --script="$(dirname "$0")/in_the_window.py" --exit
got=$(cat "$result")
if [ "$got" != "$4 $5" ]; then
  echo "the window read '$got', not '$4 $5'"
  exit 1
fi
echo "the window opened $3 with $got cells"
