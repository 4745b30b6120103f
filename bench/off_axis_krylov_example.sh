#!/usr/bin/env bash
# The worked example data/scenes/spacecraft_two_tanks_viscous.toml end to end — two full hydrazine tanks 0.6 m off a
# spacecraft's spin axis, Ek = 1.60923e-6 — with its default commands, and an independent reference: the same scene
# with the spectral sphere's response table on a window round the nutation (cavity-modes shell --sigma -0.6:0.6:61,
# docs/spherical.md §5; a wide window's table puts its fit error where the nutation's small Im R cannot carry it).
# Prints each step's time and the nutation's decay; one CSV row in OUT/off_axis_krylov_example.csv. Serial, about
# 4 minutes on the 2-core machine.
#   bash bench/off_axis_krylov_example.sh [BUILD_DIR] [OUT]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
mkdir -p "${2:-$ROOT/bench/results}"
OUT=$(cd "${2:-$ROOT/bench/results}" && pwd)
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
EK=1.60923e-6
# shellcheck source=../scripts/blas-core.sh
source "$ROOT/scripts/blas-core.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
now() { date +%s.%N; }
since() { python3 -c "print(round($(now) - $1, 1))"; }
scene() {  # TABLE OUTPUT: the example with its tanks' table replaced
  sed -e "s#\"../../out/tables/sphere_hydrazine_0.3m.h5\"#\"$1\"#" "$ROOT/data/scenes/spacecraft_two_tanks_viscous.toml" > "$2"
}
nutation_decay() {  # SCENE: the decay (1/s) of the root near the nutation's 2.227 rad/s, from spectrum --json
  "$ROM" spectrum "$1" --json | python3 -c "
import json, sys
r = [complex(*x) for x in json.load(sys.stdin)['roots']]
print(repr(min((z for z in r if z.real < 0), key=lambda z: abs(z.real + 2.227)).imag))"
}
t=$(now)
"$MODES" response sphere --radius 1 --ekman $EK --sigma -2.5:2:181 -o table.h5 > table.log 2>&1
table_s=$(since "$t")
scene "$PWD/table.h5" craft.toml
t=$(now)
table_decay=$(nutation_decay craft.toml)
spectrum_s=$(since "$t")
t=$(now)
"$ROM" confirm craft.toml --refine-tables --json --cavity-modes "$MODES" > confirm.json 2> confirm.log
confirm_s=$(since "$t")
read -r confirmed growth error < <(python3 -c "
import json
j = json.load(open('confirm.json'))
r = min(j['roots'], key=lambda q: abs(q['confirmed'][0] + 2.227))
print(repr(r['confirmed'][1]), repr(-r['growth']), repr(r['growth_error']))")
t=$(now)
"$MODES" shell --ekman $EK --sigma -0.6:0.6:61 -o spectral.h5 > spectral.log 2>&1
spectral_s=$(since "$t")
scene "$PWD/spectral.h5" spectral.toml
reference=$(nutation_decay spectral.toml)
python3 - "$OUT/off_axis_krylov_example.csv" <<EOF
import sys
rows = [("table_s", $table_s), ("spectrum_s", $spectrum_s), ("confirm_s", $confirm_s), ("spectral_table_s", $spectral_s),
        ("table_decay", $table_decay), ("confirmed_decay", $confirmed), ("finer_decay", $growth),
        ("finer_decay_error", $error), ("spectral_decay", $reference)]
with open(sys.argv[1], "w") as f:
    f.write(",".join(k for k, _ in rows) + "\n" + ",".join(repr(v) for _, v in rows) + "\n")
for k, v in rows:
    print("%-18s %s" % (k, v))
print("confirmed decay against the spectral reference: %.2e relative; the finer tables' %.2e (bar %.2e)" % (
    abs($confirmed - $reference) / $reference, abs($growth - $reference) / $reference, $error / $reference))
print("nutation time constant %.0f s (confirmed), %.0f s (spectral reference)" % (1 / $confirmed, 1 / $reference))
EOF
