#!/usr/bin/env bash
# Regenerates data/reference/*.csv from the closed forms (modes/ideal/closed_forms.cpp) with the
# make-reference-tables program (modes/app/make_reference_tables.cpp). Needs a configured build/.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build -j "$(nproc)" --target make-reference-tables > /dev/null
build/modes/make-reference-tables data/reference
