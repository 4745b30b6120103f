#!/usr/bin/env bash
# The d -> 0 limit of viscous partially filled tanks off the spin axis in the chain (docs/volume.md §8, "The response
# table and the chain"): the body of tests/scenes/viscous_fill_3d_check.py (80 kg, A 12, C 10 kg m^2, 30 rad/s, fixed
# joint, no gravity) with two spherical tanks (radius 0.2 m, filled to 0.6, 1004 kg/m^3, nu 0.012 m^2/s: Ek 1e-2)
# whose centres sit D tank radii either side of its axis: their 3-D viscous response tables (cavity-modes ellipsoid
# --fill 0.6 --axis-distance D --axis-direction 0 and 180 --ekman 1e-2 --sigma 0:3:31, P2, h 0.3) in the chain
# without axial symmetry, against Kononov's (26) with the meridian solver's response table of one such tank on the axis
# at twice the density (the two tanks at D = 0). The body's growing nutation (turning frame, its frequency and rate)
# must tend to (26)'s as D -> 0 (to the 3-D mesh's error), its shift from D = 0 growing as D^2.
# Writes OUT/viscous_fill_chain_limit.csv; about 4 minutes idle.
#   bash bench/viscous_fill_chain_limit.sh [BUILD_DIR] [OUT] [DISTANCES...]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
mkdir -p "${2:-$ROOT/bench/results}"
OUT=$(cd "${2:-$ROOT/bench/results}" && pwd)
shift $(( $# > 2 ? 2 : $# )) || true
DISTANCES=("$@")
[ ${#DISTANCES[@]} -gt 0 ] || DISTANCES=(0 0.05 0.1 0.2 0.4)
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
# shellcheck source=../scripts/blas-core.sh
source "$ROOT/scripts/blas-core.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
body='[system]\nkind = "fixed"\ngravity = 0\n[[body]]\nmass = 80.0\nA = 12.0\nC = 10.0\ncom = 0.05\nspin = 30.0\n'
tank='[[body.cavity]]\ntable = "%s"\ndensity = %s\nscale = 0.2\norigin = 0.0\noffset = [%s, 0.0]\nviscosity = 0.012\n'
"$MODES" response sphere --radius 1 --fill 0.6 --ekman 1e-2 --sigma -3:3:61 -o meridian.h5 > /dev/null 2>&1
printf "$body$tank" meridian.h5 2008.0 0.0 | sed 's/^\[\[body.cavity\]\]$/[body.cavity]/; /^offset/d; s/^origin = 0.0$/center = 0.0/' > axial.toml
csv=$OUT/viscous_fill_chain_limit.csv
echo "distance,nutation_turning,growth,axisymmetric_nutation,axisymmetric_growth,frequency_relative,growth_relative,tables_s" > "$csv"
for d in "${DISTANCES[@]}"; do
  t0=$(date +%s.%N)
  for phi in 0 180; do
    "$MODES" ellipsoid --a 1 --b 1 --c 1 --fill 0.6 --axis-distance "$d" --axis-direction "$phi" --ekman 1e-2 \
      --order 2 --mesh-size 0.3 --sigma 0:3:31 -o "t$phi.h5" > /dev/null 2>&1
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
axial = sorted(((r[0] + spin, r[1]) for r in json.load(open("axial.json"))["roots"] if -spin + 1 < r[0] < -1),
               key=lambda r: abs(r[1]))[0]
g = json.load(open("general.json"))["roots"]
got = min(g, key=lambda r: abs(r[0] - axial[0]) + abs(r[1] - axial[1]))
line = "%s,%.9f,%.9f,%.9f,%.9f,%.3e,%.3e,%s" % (d, got[0], -got[1], axial[0], -axial[1], (got[0] - axial[0]) / axial[0],
                                               (got[1] - axial[1]) / axial[1], seconds)
open(csv, "a").write(line + "\n")
print(line)
PY
done
