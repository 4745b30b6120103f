#!/usr/bin/env bash
# Regenerates data/reference/*.csv from the closed forms (modes/ideal/closed_forms.cpp) with the
# make-reference-tables program (modes/app/make_reference_tables.cpp). Needs a configured build/.
set -euo pipefail
# --help / -h: this text, nothing else (no install, no build).
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  echo "usage: bash scripts/make-reference-tables.sh"
  sed -n '2,/^set -euo/p' "$0" | grep '^#' | grep -v -- '--help / -h' | sed 's/^# \{0,1\}//'
  exit 0
fi
cd "$(dirname "$0")/.."
cmake --build build -j "$(nproc)" --target make-reference-tables > /dev/null
build/modes/make-reference-tables data/reference
