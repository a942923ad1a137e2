#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Starts a pvserver on a free port, runs client_server.py against it, stops the server.
# Usage: client_server.sh PVSERVER PVPYTHON PLUGIN FILE CELLS
set -euo pipefail
pvserver=$1 pvpython=$2 plugin=$3 file=$4 cells=$5
port=$(( 20000 + RANDOM % 20000 ))
"$pvserver" --server-port="$port" --timeout=5 >/tmp/volpost_pvserver_$port.log 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT
"$pvpython" "$(dirname "$0")/client_server.py" "$plugin" "$port" "$file" "$cells"
