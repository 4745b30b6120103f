#!/usr/bin/env bash
# The d -> 0 limit of partially filled tanks off the spin axis in the chain (docs/volume.md §8, "Off the axis, in the
# chain"): the body of tests/scenes/fill_3d_check.py (80 kg, A 12, C 10 kg m^2, 30 rad/s, fixed joint, no gravity)
# with two spheroidal tanks (c/a 0.8, radius 0.2 m, filled to 0.7, 1004 kg/m^3) whose centres sit D tank radii either
# side of its axis: their 3-D tables (cavity-modes ellipsoid --fill 0.7 --axis-distance D --axis-direction 0 and 180,
# P3, h 0.35) in the chain without axial symmetry, against Kononov's (26) with the meridian solver's table of one such
# tank on the axis at twice the density (the two tanks at D = 0). The body's nutation (turning frame) must tend to
# (26)'s as D -> 0, its shift from D = 0 growing as D^2 (the mirror image D -> -D is the same craft).
# Writes OUT/off_axis_fill_chain_limit.csv; about 4 minutes idle.
#   bash bench/off_axis_fill_chain_limit.sh [BUILD_DIR] [OUT] [DISTANCES...]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
mkdir -p "${2:-$ROOT/bench/results}"
OUT=$(cd "${2:-$ROOT/bench/results}" && pwd)
shift $(( $# > 2 ? 2 : $# )) || true
DISTANCES=("$@")
[ ${#DISTANCES[@]} -gt 0 ] || DISTANCES=(0 0.03 0.1 0.3)
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
# shellcheck source=../scripts/blas-core.sh
source "$ROOT/scripts/blas-core.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
body='[system]\nkind = "fixed"\ngravity = 0\n[[body]]\nmass = 80.0\nA = 12.0\nC = 10.0\ncom = 0.05\nspin = 30.0\n'
tank='[[body.cavity]]\ntable = "%s"\ndensity = %s\nscale = 0.2\norigin = 0.0\noffset = [%s, 0.0]\n'
"$MODES" spheroid --a 1 --c 0.8 --fill 0.7 -o meridian.h5 > /dev/null 2>&1
printf "$body$tank" meridian.h5 2008.0 0.0 | sed 's/^\[\[body.cavity\]\]$/[body.cavity]/; /^offset/d' > axial.toml
csv=$OUT/off_axis_fill_chain_limit.csv
echo "distance,nutation_turning,axisymmetric_chain,relative,tables_s,unsettled_tanks" > "$csv"
for d in "${DISTANCES[@]}"; do
  t0=$(date +%s.%N)
  for phi in 0 180; do
    "$MODES" ellipsoid --a 1 --b 1 --c 0.8 --fill 0.7 --axis-distance "$d" --axis-direction "$phi" --order 3 \
      --mesh-size 0.35 -o "t$phi.h5" > /dev/null 2>&1
  done
  tables_s=$(python3 -c "import time; print(round(time.time() - $t0, 1))")
  x=$(python3 -c "print(repr($d * 0.2))")
  { printf "$body"; printf "$tank" t0.h5 1004.0 "$x"; printf "$tank" t180.h5 1004.0 "-$x"; } > general.toml
  "$ROM" spectrum axial.toml --json > axial.json
  "$ROM" spectrum general.toml --json > general.json
  python3 - "$d" "$tables_s" "$csv" <<'PY'
import json, sys
d, seconds, csv = sys.argv[1], sys.argv[2], sys.argv[3]
spin = 30.0
axial = [r[0] + spin for r in json.load(open("axial.json"))["roots"] if -spin + 1 < r[0] < -1]
assert len(axial) == 1, axial
g = json.load(open("general.json"))
got = min((r[0] for r in g["roots"]), key=lambda x: abs(x - axial[0]))
rows = len(g["not_converged"])  # the tanks whose rows did not settle (their notes)
line = "%s,%.9f,%.9f,%.3e,%s,%s" % (d, got, axial[0], (got - axial[0]) / axial[0], seconds, rows)
open(csv, "a").write(line + "\n")
print(line)
PY
done
