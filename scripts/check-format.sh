#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Checks that the C++ lines changed since .ci/format-base follow .clang-format (clang-format
# 14's clang-format-diff): prints what it would change and exits 1 when anything would.
# Code older than the base is left as it is; a session that formats more moves the base.
#   scripts/check-format.sh          check
#   scripts/check-format.sh --fix    format those lines in place
set -euo pipefail
cd "$(dirname "$0")/.."
diff_tool=$(command -v clang-format-diff-14 || command -v clang-format-diff || true)
if [ -z "$diff_tool" ]; then
  echo "check-format: clang-format-diff is not installed (apt-get install clang-format)" >&2
  exit 1
fi
base=$(cat .ci/format-base)
if ! git cat-file -e "$base^{commit}" 2>/dev/null; then
  echo "check-format: the base commit $base of .ci/format-base is not in this clone" >&2
  exit 1
fi
changes=$(git diff -U0 --no-color "$base" -- '*.cpp' '*.hpp')
if [ "${1:-}" = "--fix" ]; then
  printf '%s\n' "$changes" | "$diff_tool" -p1 -i
  exit 0
fi
report=$(printf '%s\n' "$changes" | "$diff_tool" -p1)
if [ -n "$report" ]; then
  printf '%s\n' "$report"
  echo "check-format: lines changed since $base do not follow .clang-format (scripts/check-format.sh --fix)" >&2
  exit 1
fi
echo "check-format: the lines changed since $base follow .clang-format"
