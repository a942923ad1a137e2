#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# "volpost Volume" and ParaView's own Volume on 1, 2 and 4 MPI ranks, composited, against the
# one-process picture (parallel_composite.py). Where expat defers parsing, the ranks run with
# the library that makes it parse eagerly preloaded (without it ParaView 5.11 on Debian 12
# cannot move the pieces: docs/user/paraview.md; PRELOAD "none" where expat does not defer);
# a log that still shows that failure fails the test.
# Usage: parallel_composite.sh MPIRUN PVBATCH PLUGIN PRELOAD|none OUTDIR
set -euo pipefail
mpirun=$1 pvbatch=$2 plugin=$3 preload=$4 outdir=$5
[ "$preload" = none ] && preload=
script="$(dirname "$0")/parallel_composite.py"
mkdir -p "$outdir"
rm -f "$outdir"/*.png "$outdir"/*.log
for ranks in 1 2 4; do
  for representation in "volpost Volume" "volpost Volume, clipped" "Volume" "volpost Volume, cells' own field" \
      "volpost Volume, tetrahedra of hexahedra"; do
    name=${representation//, /_}
    name=${name//\'/}
    log="$outdir/${name// /_}$ranks.log"
    if ! "$mpirun" --allow-run-as-root --oversubscribe -np "$ranks" -x LD_PRELOAD="$preload" \
        "$pvbatch" --mpi "$script" render "$plugin" "$representation" "$outdir" >"$log" 2>&1; then
      echo "FAIL: $representation on $ranks rank(s) (log: $log)"; tail -20 "$log"; exit 1
    fi
    if grep -q "Error parsing XML" "$log"; then
      echo "FAIL: $representation on $ranks rank(s): pieces moved between ranks were not read (log: $log)"
      grep -m 3 "Error parsing XML" "$log"; exit 1
    fi
  done
done
"$pvbatch" "$script" compare "$outdir" 2 4
