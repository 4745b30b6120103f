#!/usr/bin/env bash
# docs/trust.md's viscous rows at Ek = 1e-6: every built-in axisymmetric shape, completely filled and at two fills,
# through bench/viscous_fill_study.sh (the default table, spectrum, confirm and a P4/P5 reference at a quarter of the
# table's element size), one CSV row each in OUT/viscous_fill_study.csv. About 80 minutes on this 2-core machine.
#   bash bench/viscous_fill_campaign.sh [BUILD_DIR] [OUT] [EKMAN] [FILLS]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build}
OUT=${2:-$ROOT/bench/results}
EK=${3:-1e-6}
FILLS=${4:-"1 0.8 0.5"}
# shellcheck source=../scripts/blas-core.sh
source "$ROOT/scripts/blas-core.sh"
shapes=("sphere --radius 1" "spheroid --a 1 --c 0.666667" "cylinder --radius 1 --height 2" "cone --radius 1 --height 1.5")
for fill in $FILLS; do
  for shape in "${shapes[@]}"; do
    echo "== $shape, fill $fill, Ek $EK ($(date +%T))"
    bash "$ROOT/bench/viscous_fill_study.sh" "$shape" "$fill" "$EK" "$BUILD" "$OUT"
  done
done
