#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds volpost with AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/), runs the
# unit, plugin and command-line tests under them, then every command-line verb on every
# hostile and broken file (tests/data/hostile, tests/data/bad, the seismic and image-data test
# files, and ../shared/data/hostile, ../shared/data/bad and ../shared/data/seismic when present). Any sanitizer report or crash fails the script. Run it
# before handing work in:   scripts/sanitize.sh            (about 25 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
if [ ! -f build-asan/CMakeCache.txt ]; then
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVOLPOST_BUILD_BENCH=OFF \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
fi
cmake --build build-asan
# Leaks are not errors here (Qt and Mesa keep singletons to exit); everything else is.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=0:exitcode=86
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:exitcode=87
export VOLPOST_TESTS_UNDER_ASAN=1  # ASan's shadow memory cannot live under ulimit -v
ctest --test-dir build-asan -L "unit|cli|plugin" -j2 --output-on-failure
# The volume renderers' image tests too (about 3 minutes under the sanitizers): they drive
# the CPU marchers and the GPU renderers' host code on real frames.
build-asan/bin/raycast_tests --gtest_brief=1

volpost=build-asan/bin/volpost
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failures=0
check() {  # runs volpost with a time limit; a sanitizer report or a crash is a failure
  local log="$out/log" rc=0
  timeout 120 "$volpost" "$@" >"$log" 2>&1 || rc=$?
  if [ "$rc" -ge 86 ] && [ "$rc" -ne 124 ] || grep -q "AddressSanitizer\|runtime error\|terminate called" "$log"; then
    echo "FAILED (exit $rc): volpost $*"
    head -30 "$log"
    failures=$((failures + 1))
  fi
}
files=(tests/data/hostile/* tests/data/bad/* tests/data/seismic/*.sgy tests/data/formats/*.vti)
for dir in ../shared/data/hostile ../shared/data/bad ../shared/data/seismic/segyio; do [ -d "$dir" ] && files+=("$dir"/*); done
for f in "${files[@]}"; do
  case "$f" in *.md|*.json) continue ;; esac
  check info "$f"
  check convert "$f" "$out/c.vtu"
  check surface "$f" "$out/s.stl"
  for q in $("$volpost" info "$f" 2>/dev/null | awk '/^fields:/ {on=1; next} on && /^  [^ ]/ {print $1; exit}'); do
    check probe "$f" --field "$q" --at 0,0,0
    check render "$f" --field "$q" --size 32x24 -o "$out/r.png"
    check render "$f" --field "$q" --size 32x24 --renderer reference -o "$out/r.png"
    check render "$f" --field "$q" --size 32x24 --renderer raycast -o "$out/r.png"
    check render "$f" --field "$q" --size 32x24 --renderer cpu --clip 0,0,0,1,0,0 --iso 0 -o "$out/r.png"
    check render "$f" --field "$q" --size 32x24 --renderer texture-raymarch --shading --iso 0 -o "$out/r.png"
    check render "$f" --field "$q" --size 32x24 --renderer texture-slices -o "$out/r.png"
    check render "$f" --field "$q" --size 32x24 --clip 0,0,0,1,0,0 --iso 0 --deform "${q%%.*}" -o "$out/r.png"
    check render "$f" --field "$q" --size 32x24 --all-steps -o "$out/a.png"
    check plot "$f" --field "$q" --from 0,0,0 --to 1,1,1 --samples 20 --csv "$out/p.csv" -o "$out/p.png"
  done
done
for tf in tests/data/hostile/*.json; do
  check render tests/data/hostile/seed.vtu --field T --renderer raycast --tf "$tf" --size 32x24 -o "$out/t.png"
  check render tests/data/hostile/seed.vtu --field T --renderer cpu --tf "$tf" --size 32x24 -o "$out/t.png"
done
echo "sanitizers: ${#files[@]} files through every verb, $failures failure(s)"
[ "$failures" -eq 0 ]
