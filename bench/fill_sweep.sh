#!/usr/bin/env bash
# The fill of the spacecraft's two tanks off its axis swept from 0.2 to 1 (data/scenes/spacecraft_fill_tanks.toml:
# 800 kg, A 400, C 520 kg m^2, 60 rpm, free; two spheres of radius 0.3 m at +-0.6 m, hydrazine, ideal): at each fill
# both tanks' 3-D tables (cavity-modes ellipsoid --fill F --axis-distance 2 --axis-direction 0 and 180, at ORDER and
# the default mesh; a full tank's table without the axis options, placed by the scene's offset), then chain-rom
# spectrum on the free chain: its nutation in the turning frame, the verdict, whether a tank's rows did not settle,
# and the rows' coverage of the sum rule. Writes OUT/fill_sweep.csv and OUT/fill_sweep.png; about 2 minutes idle at
# ORDER 3 (docs/volume.md section 8, "The free chain").
#   bash bench/fill_sweep.sh [BUILD_DIR] [OUT] [ORDER]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
mkdir -p "${2:-$ROOT/bench/results}"
OUT=$(cd "${2:-$ROOT/bench/results}" && pwd)
ORDER=${3:-3}
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
# shellcheck source=../scripts/blas-core.sh
source "$ROOT/scripts/blas-core.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
csv=$OUT/fill_sweep.csv
echo "fill,nutation_turning,stable,unsettled_tanks,coverage_0,coverage_180,tables_s" > "$csv"
for fill in 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9 1; do
  t0=$(date +%s.%N)
  for phi in 0 180; do
    if [ "$fill" = 1 ]; then place=(); else place=(--fill "$fill" --axis-distance 2 --axis-direction "$phi"); fi
    "$MODES" ellipsoid --a 1 --b 1 --c 1 "${place[@]}" --order "$ORDER" -o "t$phi.h5" > "t$phi.log" 2>&1 ||
      { echo "fill_sweep.sh: cavity-modes failed at fill $fill: $(tail -1 "t$phi.log")" >&2; exit 1; }
  done
  tables_s=$(python3 -c "import time; print(round(time.time() - $t0, 1))")
  sed -e 's|"../../out/tables/fill_tank_\([0-9]*\).h5"|"t\1.h5"|' "$ROOT/data/scenes/spacecraft_fill_tanks.toml" > scene.toml
  "$ROM" spectrum scene.toml --json > spectrum.json
  python3 - "$fill" "$tables_s" "$csv" <<'PY'
import json, sys
fill, seconds, csv = sys.argv[1:4]
j = json.load(open("spectrum.json"))
tilts = [r[0] for r in j["roots"] if 0.5 < r[0] < 4]  # the nutation (turning frame)
nut = min(tilts) if tilts else float("nan")
cov = [c[1] for c in j["coverage"]] + [float("nan")] * 2
line = "%s,%.9f,%s,%d,%.4f,%.4f,%s" % (fill, nut, j["stable"], len(j["not_converged"]), cov[0], cov[1], seconds)
open(csv, "a").write(line + "\n")
print(line, flush=True)
PY
done
/usr/bin/python3 - "$csv" "$OUT/fill_sweep.png" <<'PY'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = list(csv.DictReader(open(sys.argv[1])))
f = [float(r["fill"]) for r in rows]
n = [float(r["nutation_turning"]) for r in rows]
bad = [int(r["unsettled_tanks"]) > 0 for r in rows]
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(f, n, "-", color="0.6")
ax.plot([x for x, b in zip(f, bad) if not b], [y for y, b in zip(n, bad) if not b], "o", label="rows settled")
ax.plot([x for x, b in zip(f, bad) if b], [y for y, b in zip(n, bad) if b], "s", mfc="none",
        label="a tank's rows NOT CONVERGED")
ax.set_xlabel("fill of each tank")
ax.set_ylabel("nutation in the turning frame (rad/s)")
ax.set_title("two tanks 0.6 m off the axis, 60 rpm, free (ideal liquid)")
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
PY
echo "wrote $csv and $OUT/fill_sweep.png"
