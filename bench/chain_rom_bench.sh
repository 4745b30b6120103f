#!/usr/bin/env bash
# chain-rom benchmark: error against run time and the speed targets, on the default scene's
# real mode tables. Benchmarks, not tests; figures go into docs/benchmarks.md ("chain-rom").
#
#   bash bench/chain_rom_bench.sh [--repeat N]
#
#  1. mode tables: out/tables/*.h5 from the "# recipe:" lines of data/scenes/default_ideal.toml, made with
#     build/modes/cavity-modes if missing (as scripts/run-default.sh does; ~70 s on 2 cores);
#  2. chain-rom bench data/scenes/default_ideal.toml: work-precision (exact / gauss / rk45 against the long
#     double reference) and roots against kept modes -> bench/results/chain_rom_<date>.csv and .png;
#  3. speed, N runs each (default 3), /usr/bin/time around the process:
#     a. chain-rom run bench/scenes/three_bodies_20_modes.toml (3 bodies x 20 modes, 1e5 output steps,
#        exact): the propagation's own wall and CPU time as printed, plus the whole process (HDF5 write of
#        ~100 MB included) — target < 0.2 s;
#     b. chain-rom sweep, 100 x 100 map of data/scenes/default_ideal.toml (body[1].spin x joint[1].stiffness)
#        — target < 10 s;
#     c. the same for data/scenes/default.toml (water; joint stiffnesses) when its tables exist — target < 10 s;
#     with the 1-minute load average before each run (the machine may be shared);
#  4. bench/results/chain_rom_<date>_speed.md: machine, date, commit, load and every timing.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$ROOT/scripts/blas-core.sh"
REPEAT=3
if [ "${1:-}" = "--repeat" ]; then REPEAT="${2:?--repeat N}"; fi
ROM="$ROOT/build/rom/chain-rom"
MODES="$ROOT/build/modes/cavity-modes"
SCENE="$ROOT/data/scenes/default_ideal.toml"
SPEED_SCENE="$ROOT/bench/scenes/three_bodies_20_modes.toml"
RES="$ROOT/bench/results"
DATE=$(date +%F)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
[ -x "$ROM" ] || { echo "chain_rom_bench: $ROM not built (bash scripts/build.sh)" >&2; exit 1; }
mkdir -p "$RES" "$ROOT/out/tables"
load1() { cut -d' ' -f1 /proc/loadavg; }

echo "[1/4] mode tables"
while IFS= read -r recipe; do
  name="${recipe%%:*}"
  read -r -a args <<< "${recipe#*:}"
  if [ ! -f "$ROOT/out/tables/$name" ]; then
    [ -x "$MODES" ] || { echo "chain_rom_bench: $MODES not built" >&2; exit 1; }
    echo "  $name: cavity-modes ${args[*]}"
    "$MODES" "${args[@]}" -o "$ROOT/out/tables/$name" > "$TMP/$name.log"
  else
    echo "  $name: present"
  fi
done < <(sed -n 's/^# recipe: //p' "$SCENE")

echo "[2/4] chain-rom bench (load $(load1))"
"$ROM" bench "$SCENE" -o "$RES/chain_rom_$DATE.csv" --png "$RES/chain_rom_$DATE.png" | tee "$TMP/bench.txt"

MD="$RES/chain_rom_${DATE}_speed.md"
{
  echo "# chain-rom speed, $DATE"
  echo
  echo "- machine: $(nproc) CPUs, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"\
       "$(awk '/MemTotal/ {printf "%.1f GiB", $2/1048576}' /proc/meminfo), $(uname -sr)"
  echo "- commit: $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet -- rom || echo ' (rom/ modified)')"
  echo "- AVX2/FMA: $(grep -m1 -o -w avx2 /proc/cpuinfo || echo no) (exact propagation's product kernel)"
  echo
  echo "## Work-precision and roots against kept modes (chain-rom bench data/scenes/default_ideal.toml)"
  echo
  echo '```'
  cat "$TMP/bench.txt"
  echo '```'
  echo
  echo "## 3 bodies x 20 modes, 1e5 output steps, exact (target < 0.2 s)"
  echo
  echo "| run | load before | propagation wall | propagation CPU | process wall | process user+sys |"
  echo "|---|---|---|---|---|---|"
} > "$MD"

echo "[3/4] speed: 1e5 output steps, exact"
for i in $(seq "$REPEAT"); do
  l=$(load1)
  /usr/bin/time -f "%e %U %S" -o "$TMP/time" "$ROM" run "$SPEED_SCENE" -o "$TMP/traj.h5" > "$TMP/run.txt"
  read -r wall user sys < "$TMP/time"
  line=$(head -n1 "$TMP/run.txt")
  pw=$(sed -E 's/.*, ([0-9.e+-]+) s \(CPU ([0-9.e+-]+) s\)$/\1/' <<< "$line")
  pc=$(sed -E 's/.*, ([0-9.e+-]+) s \(CPU ([0-9.e+-]+) s\)$/\2/' <<< "$line")
  echo "  run $i: load $l, propagation $pw s (CPU $pc s), process $wall s (user+sys $(awk "BEGIN {print $user + $sys}") s)"
  echo "| $i | $l | $pw s | $pc s | $wall s | $(awk "BEGIN {print $user + $sys}") s |" >> "$MD"
  rm -f "$TMP/traj.h5"
done
echo >> "$MD"
sed -n 2p "$TMP/run.txt" >> "$MD"

# time_map TITLE SCENE SWEEP-ARGS...: REPEAT timed runs of a 100 x 100 sweep, a table of them in $MD.
time_map() {
  local title=$1 scene=$2
  shift 2
  {
    echo
    echo "## 100 x 100 $title (target < 10 s)"
    echo
    echo "| run | load before | sweep (as printed) | roots | process wall | process user+sys |"
    echo "|---|---|---|---|---|---|"
  } >> "$MD"
  echo "[4/4] speed: 100 x 100 $title"
  for i in $(seq "$REPEAT"); do
    l=$(load1)
    /usr/bin/time -f "%e %U %S" -o "$TMP/time" "$ROM" sweep "$scene" "$@" -o "$TMP/map.csv" > "$TMP/sweep.txt" 2>/dev/null
    read -r wall user sys < "$TMP/time"
    s=$(grep -o '[0-9.]* s on [0-9]* thread[s]*' "$TMP/sweep.txt")
    roots=$(grep -o '[0-9]* points tracked' "$TMP/sweep.txt")
    echo "  run $i: load $l, $s, $roots, process $wall s"
    echo "| $i | $l | $s | $roots | $wall s | $(awk "BEGIN {print $user + $sys}") s |" >> "$MD"
  done
}

time_map "stability map of the ideal default scene" "$SCENE" --param 'body[1].spin' --from 100 --to 400 --steps 100 \
  --param2 'joint[1].stiffness' --from2 0 --to2 400 --steps2 100
# The water scene (data/scenes/default.toml: three response-fit tables, 260 roots a point) when its tables exist
# (bash scripts/run-default.sh makes them): growth rate over the joints' stiffnesses, roots tracked point to point.
WATER="$ROOT/data/scenes/default.toml"
if sed -n 's/^# recipe: \([^:]*\):.*/\1/p' "$WATER" | while read -r t; do [ -f "$ROOT/out/tables/$t" ] || exit 1; done; then
  time_map "growth-rate map of the water default scene" "$WATER" --param 'joint[1].stiffness' --from 0 --to 400 \
    --steps 100 --param2 'joint[2].stiffness' --from2 0 --to2 400 --steps2 100
else
  echo "[4/4] water map skipped: its tables are not in out/tables (bash scripts/run-default.sh makes them)"
fi
echo "wrote $RES/chain_rom_$DATE.csv, $RES/chain_rom_$DATE.png, $MD"
