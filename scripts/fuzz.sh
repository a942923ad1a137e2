#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fuzzes every reader with libFuzzer (clang, ASan + UBSan) for a bounded time each,
# starting from the test files of its format and the hostile files; a structural mutator
# (ReaderFuzzTarget.cpp) replaces counts with hostile values, repeats sections and cuts
# files short. Declared sizes past a 1 GB memory budget are refused, as a user's would be. A crash leaves its input in
# build-fuzz/crashes/<reader>/; fixed crashes are kept in tests/data/fuzz/ where the unit
# tests read them (meshio_tests: FuzzRegressions).
#   scripts/fuzz.sh [SECONDS_PER_READER]   (default 60)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
command -v clang++ >/dev/null || { echo "fuzz: needs clang (apt-get install clang)"; exit 2; }
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DVOLPOST_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz
declare -A seeds=(
  [gmsh]="tests/data/bad/*.msh tests/data/formats/*.msh tests/data/hostile/*.msh"
  [inp]="tests/data/bad/*.inp tests/data/formats/*.inp tests/data/hostile/*.inp"
  [frd]="tests/data/bad/*.frd tests/data/formats/*.frd"
  [nf]="tests/data/formats/*.nf"
  [vtk]="tests/data/bad/*.vtk tests/data/hostile/*.vtk"
  [vtu]="tests/data/bad/*.vtu tests/data/formats/*.vtu tests/data/hostile/*.vtu"
  [exo]="tests/data/bad/*.exo tests/data/hostile/*.exo"
)
export VOLPOST_MEMORY_BUDGET=1G
status=0
for reader in gmsh inp frd nf vtk vtu exo; do
  corpus="build-fuzz/corpus/$reader"
  crashes="build-fuzz/crashes/$reader"
  mkdir -p "$corpus" "$crashes"
  for f in ${seeds[$reader]}; do [ -f "$f" ] && cp -n "$f" "$corpus/" || true; done
  for f in tests/data/fuzz/$reader/*; do [ -f "$f" ] && cp -n "$f" "$corpus/" || true; done
  echo "== fuzz_$reader: ${seconds}s"
  if ! build-fuzz/bin/fuzz_$reader -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
      -max_len=65536 -artifact_prefix="$crashes/" -print_final_stats=1 "$corpus" 2>"build-fuzz/fuzz_$reader.log"; then
    echo "fuzz_$reader: FOUND A CRASH (see build-fuzz/fuzz_$reader.log and $crashes)"
    status=1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "build-fuzz/fuzz_$reader.log" | tr '\n' ' '
  echo
done
exit $status
