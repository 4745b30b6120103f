#!/usr/bin/env bash
# The d -> 0 limit of partially filled tanks off the spin axis in the chain (docs/volume.md §8, "Off the axis, in the
# chain", and "The response table and the chain"): the body of tests/scenes/fill_3d_check.py and
# viscous_fill_3d_check.py (80 kg, A 12, C 10 kg m^2, 30 rad/s, fixed joint, no gravity) with two tanks (radius 0.2 m,
# 1004 kg/m^3) whose centres sit D tank radii either side of its axis: their 3-D tables (cavity-modes ellipsoid --fill
# F --axis-distance D --axis-direction 0 and 180) in the chain without axial symmetry, against Kononov's (26) with the
# meridian solver's table of one such tank on the axis at twice the density (the two tanks at D = 0). The body's
# nutation (turning frame) must tend to (26)'s as D -> 0 (to the 3-D mesh's error), its shift from D = 0 growing as
# D^2 (the mirror image D -> -D is the same craft).
#   LIQUID ideal:   spheroidal tanks (c/a 0.8) filled to 0.7, mode tables (P3, h 0.35); the nutation's frequency.
#   LIQUID viscous: spherical tanks filled to 0.6, nu 0.012 m^2/s (Ek 1e-2), response tables (--ekman 1e-2 --sigma
#                   0:3:31, P2, h 0.3); the growing nutation's frequency and rate.
# KIND=free puts the body in free flight (both chains free: (26)'s base eliminated in the complex chain, the general
# chain's recoiling with the liquid, docs/volume.md §8 "The free chain"), the files ending _free.csv.
# Writes OUT/off_axis_fill_chain_limit.csv (ideal) or OUT/viscous_fill_chain_limit.csv; about 4 minutes idle each.
#   [KIND=fixed|free] bash bench/fill_chain_limit.sh ideal|viscous [BUILD_DIR] [OUT] [DISTANCES...]
set -euo pipefail
LIQUID=${1:-}
case "$LIQUID" in
  ideal | viscous) shift ;;
  *) echo "fill_chain_limit.sh: the first argument is the liquid, ideal or viscous (not '$LIQUID')" >&2; exit 1 ;;
esac
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
mkdir -p "${2:-$ROOT/bench/results}"
OUT=$(cd "${2:-$ROOT/bench/results}" && pwd)
shift $(( $# > 2 ? 2 : $# )) || true
DISTANCES=("$@")
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
# shellcheck source=../scripts/blas-core.sh
source "$ROOT/scripts/blas-core.sh"
tank='[[body.cavity]]\ntable = "%s"\ndensity = %s\nscale = 0.2\norigin = 0.0\noffset = [%s, 0.0]\n'
to_axis='s/^\[\[body.cavity\]\]$/[body.cavity]/; /^offset/d'  # one tank on the axis: (26)'s cavity keys
KIND=${KIND:-fixed}
case "$KIND" in
  fixed) suffix= ;;
  free) suffix=_free ;;
  *) echo "fill_chain_limit.sh: KIND is fixed or free, not '$KIND'" >&2; exit 1 ;;
esac
if [ "$LIQUID" = ideal ]; then
  [ ${#DISTANCES[@]} -gt 0 ] || DISTANCES=(0 0.03 0.1 0.3)
  meridian=(spheroid --a 1 --c 0.8 --fill 0.7)
  volume=(ellipsoid --a 1 --b 1 --c 0.8 --fill 0.7 --order 3 --mesh-size 0.35)
  csv=$OUT/off_axis_fill_chain_limit$suffix.csv
  header="distance,nutation_turning,axisymmetric_chain,relative,tables_s,unsettled_tanks"
else
  [ ${#DISTANCES[@]} -gt 0 ] || DISTANCES=(0 0.05 0.1 0.2 0.4)
  tank=$tank'viscosity = 0.012\n'
  to_axis=$to_axis'; s/^origin = 0.0$/center = 0.0/'
  meridian=(response sphere --radius 1 --fill 0.6 --ekman 1e-2 --sigma -3:3:61)
  volume=(ellipsoid --a 1 --b 1 --c 1 --fill 0.6 --ekman 1e-2 --order 2 --mesh-size 0.3 --sigma 0:3:31)
  csv=$OUT/viscous_fill_chain_limit$suffix.csv
  header="distance,nutation_turning,growth,axisymmetric_nutation,axisymmetric_growth,frequency_relative,growth_relative,tables_s"
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
body='[system]\nkind = "'$KIND'"\ngravity = 0\n[[body]]\nmass = 80.0\nA = 12.0\nC = 10.0\ncom = 0.05\nspin = 30.0\n'
"$MODES" "${meridian[@]}" -o meridian.h5 > /dev/null 2>&1
printf "$body$tank" meridian.h5 2008.0 0.0 | sed "$to_axis" > axial.toml
echo "$header" > "$csv"
for d in "${DISTANCES[@]}"; do
  t0=$(date +%s.%N)
  for phi in 0 180; do
    "$MODES" "${volume[@]}" --axis-distance "$d" --axis-direction "$phi" -o "t$phi.h5" > /dev/null 2>&1
  done
  tables_s=$(python3 -c "import time; print(round(time.time() - $t0, 1))")
  x=$(python3 -c "print(repr($d * 0.2))")
  { printf "$body"; printf "$tank" t0.h5 1004.0 "$x"; printf "$tank" t180.h5 1004.0 "-$x"; } > general.toml
  "$ROM" spectrum axial.toml --json > axial.json
  "$ROM" spectrum general.toml --json > general.json
  python3 - "$LIQUID" "$d" "$tables_s" "$csv" <<'PY'
import json, sys
liquid, d, seconds, csv = sys.argv[1:5]
spin = 30.0
# (26)'s nutation in the turning frame: its space-frame roots shifted by the spin.
axial = [(r[0] + spin, r[1]) for r in json.load(open("axial.json"))["roots"] if -spin + 1 < r[0] < -1]
g = json.load(open("general.json"))
if liquid == "ideal":
    # The nutation: the lowest root there (a free chain has a fluid root near 11 rad/s too, the tanks' even modes
    # coupled through the base's translation).
    a = min(axial, key=lambda r: abs(r[0]))[0]
    got = min((r[0] for r in g["roots"]), key=lambda x: abs(x - a))
    rows = len(g["not_converged"])  # the tanks whose rows did not settle (their notes)
    line = "%s,%.9f,%.9f,%.3e,%s,%s" % (d, got, a, (got - a) / a, seconds, rows)
else:
    a = sorted(axial, key=lambda r: abs(r[1]))[0]  # the one nearest the real axis: the nutation the liquid drives
    got = min(g["roots"], key=lambda r: abs(r[0] - a[0]) + abs(r[1] - a[1]))
    line = "%s,%.9f,%.9f,%.9f,%.9f,%.3e,%.3e,%s" % (d, got[0], -got[1], a[0], -a[1], (got[0] - a[0]) / a[0],
                                                   (got[1] - a[1]) / a[1], seconds)
open(csv, "a").write(line + "\n")
print(line)
PY
done
