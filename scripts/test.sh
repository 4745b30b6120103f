#!/usr/bin/env bash
# The test command of README.md: set-up, build, then the whole ctest suite.
set -euo pipefail
# --help / -h: this text, nothing else (no install, no build).
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  echo "usage: bash scripts/test.sh [CTEST_ARGS...]   (e.g. -R Viscous)"
  sed -n '2,/^set -euo/p' "$0" | grep '^#' | grep -v -- '--help / -h' | sed 's/^# \{0,1\}//'
  exit 0
fi
cd "$(dirname "$0")/.."
source scripts/blas-core.sh
start=$SECONDS
bash scripts/build.sh
built=$SECONDS
cd build
status=0
ctest --output-on-failure -j "$(nproc)" "$@" || status=$?
# The suite's cost in one line, so that a regression shows the day it lands (README.md gives the measured figures).
echo "test.sh: set-up and build $((built - start)) s, ctest $((SECONDS - built)) s, in all $((SECONDS - start)) s"
exit "$status"
