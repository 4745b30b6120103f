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
bash scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)" "$@"
