#!/usr/bin/env bash
# The default job of README.md, runnable from any folder:
#   1. install what is missing and build the two programs (scripts/build.sh cavity-modes chain-rom -> build/;
#      the test suite is built by scripts/test.sh),
#   2. make the mode tables of data/scenes/default.toml (water: three Krylov response tables of the viscous
#      fluid) and of data/scenes/default_ideal.toml (the same chain with ideal fluid, for comparison) with
#      cavity-modes into out/tables/ (the "# recipe:" lines of each scene; a table is remade only when it is
#      missing or older than the cavity-modes binary or its scene),
#   3. chain-rom spectrum on the default scene: roots, growth rates and stability verdict (also saved to
#      out/default-spectrum.txt), then on the ideal one (out/default-ideal-spectrum.txt) and the two verdicts,
#   4. chain-rom run: time history out/default-trajectory.h5,
#   5. plot it: out/default-trajectory.png (scripts/plot_trajectory.py, Debian's /usr/bin/python3),
#   6. chain-rom sweep: map of the growth rate over the two joints' stiffnesses (100 x 100 points),
#      out/default-map.csv and out/default-map.png (scripts/plot_sweep.py). (A viscous table holds for one
#      Ekman number, so with water the map cannot sweep a spin: docs/rom.md, "Viscous tanks".)
# Exits non-zero on the first failure.
set -euo pipefail
# --help / -h: this text, nothing else (no install, no build).
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  echo "usage: bash scripts/run-default.sh"
  sed -n '2,/^set -euo/p' "$0" | grep '^#' | grep -v -- '--help / -h' | sed 's/^# \{0,1\}//'
  exit 0
fi

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SCENE="$ROOT/data/scenes/default.toml"
IDEAL="$ROOT/data/scenes/default_ideal.toml"
OUT="$ROOT/out"
TABLES="$OUT/tables"
MODES="$ROOT/build/modes/cavity-modes"
ROM="$ROOT/build/rom/chain-rom"
PY=/usr/bin/python3
source "$ROOT/scripts/blas-core.sh"
START=$SECONDS

step() { printf '\n[run-default %3ds] %s\n' "$((SECONDS - START))" "$*"; }
fail() { printf '[run-default] FAILED: %s\n' "$*" >&2; exit 1; }

step "1/6 install and build the programs (scripts/build.sh cavity-modes chain-rom)"
bash "$ROOT/scripts/build.sh" cavity-modes chain-rom || fail "scripts/build.sh"
[ -x "$MODES" ] || fail "$MODES was not built (RC_BUILD_MODES off?)"
[ -x "$ROM" ] || fail "$ROM was not built (RC_BUILD_ROM off?)"
[ -x "$PY" ] || fail "$PY not found (Debian python3 with python3-h5py, python3-matplotlib)"

step "2/6 mode tables -> ${TABLES#"$ROOT"/}"
mkdir -p "$TABLES"
RECIPES=()
for scene in "$SCENE" "$IDEAL"; do
  mapfile -t lines < <(sed -n 's/^# recipe: //p' "$scene")
  [ "${#lines[@]}" -gt 0 ] || fail "no '# recipe:' lines in $scene"
  for line in "${lines[@]}"; do RECIPES+=("$scene|$line"); done
done
for entry in "${RECIPES[@]}"; do
  scene="${entry%%|*}"
  recipe="${entry#*|}"
  name="${recipe%%:*}"
  read -r -a args <<< "${recipe#*:}"
  table="$TABLES/$name"
  if [ -f "$table" ] && [ "$table" -nt "$MODES" ] && [ "$table" -nt "$scene" ]; then
    echo "  $name: up to date, kept (cavity-modes ${args[*]})"
    continue
  fi
  # A response table's forced solves are shared out between the cores under mpirun (docs/viscous.md, "Response fit").
  launcher=()
  if [ "${args[0]}" = response ] && [ "$(nproc)" -gt 1 ] && command -v mpirun > /dev/null; then
    launcher=(env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 mpirun -n "$(nproc)")
  fi
  echo "  $name: ${launcher[*]:+mpirun -n $(nproc) }cavity-modes ${args[*]} ..."
  t0=$SECONDS
  log="$TABLES/${name%.h5}.log"
  : > "$log"
  # The table report goes to the log; the progress lines (stderr, at least every 5 s) also to the terminal.
  status=0
  "${launcher[@]}" "$MODES" "${args[@]}" -o "$table" 2>&1 >> "$log" | tee -a "$log" | sed -u 's/^/    /' >&2 || status=$?
  if [ "$status" -ne 0 ] && [ "${#launcher[@]}" -gt 0 ]; then
    # mpirun itself can fail where OpenMPI cannot start; serially the table reads back the solves already made
    # (FILE.h5.samples, docs/viscous.md "Response fit").
    echo "  $name: failed under mpirun (log: $log); once more, serially" >&2
    status=0
    "$MODES" "${args[@]}" -o "$table" 2>&1 >> "$log" | tee -a "$log" | sed -u 's/^/    /' >&2 || status=$?
  fi
  if [ "$status" -ne 0 ]; then
    tail -n 20 "$log" >&2
    fail "cavity-modes ${args[*]} (log: $log)"
  fi
  # one-line summary: mesh and dofs, coverage, number of clusters
  summary=$(grep -m1 'dofs' "$TABLES/${name%.h5}.log" || true)
  coverage=$(grep -o 'coverage [0-9.eE+-]*' "$TABLES/${name%.h5}.log" | head -n1 || true)
  echo "  $name: written in $((SECONDS - t0)) s; $summary; $coverage"
  # The table's own line on unconverged clusters (docs/trust.md), if it has one.
  grep -m1 '^note:' "$log" | sed 's/^/    /' || true
done

step "3/6 chain-rom spectrum ${SCENE#"$ROOT"/} (water), then ${IDEAL#"$ROOT"/} (ideal fluid)"
"$ROM" spectrum "$SCENE" > "$OUT/default-spectrum.txt" || { cat "$OUT/default-spectrum.txt"; fail "chain-rom spectrum"; }
cat "$OUT/default-spectrum.txt"
"$ROM" spectrum "$IDEAL" > "$OUT/default-ideal-spectrum.txt" ||
  { cat "$OUT/default-ideal-spectrum.txt"; fail "chain-rom spectrum (ideal)"; }
echo "  water: $(grep -m1 '^stable:' "$OUT/default-spectrum.txt"); $(grep -m1 '^largest growth' "$OUT/default-spectrum.txt")"
echo "  ideal fluid: $(grep -m1 '^stable:' "$OUT/default-ideal-spectrum.txt")"

step "4/6 chain-rom run -> out/default-trajectory.h5"
"$ROM" run "$SCENE" -o "$OUT/default-trajectory.h5" || fail "chain-rom run"

step "5/6 plot -> out/default-trajectory.png"
# The growth is far slower than the run (e-folding in about 75 s against 5 s of motion): the title says so, so that a
# plot without visible growth is not read as stable.
efold=$(sed -n 's/^stable: no .*(e-folding \([0-9.e+-]*\) s).*/\1/p' "$OUT/default-spectrum.txt" | head -1)
title="default scene (data/scenes/default.toml)"
[ -n "$efold" ] && title="$title: unstable, e-folding in $(printf '%.0f' "$efold") s (too slow to see in this run)"
"$PY" "$ROOT/scripts/plot_trajectory.py" "$OUT/default-trajectory.h5" -o "$OUT/default-trajectory.png" \
  --title "$title" || fail "scripts/plot_trajectory.py"

step "6/6 growth-rate map -> out/default-map.png (joint[1].stiffness 0..400 x joint[2].stiffness 0..400)"
"$ROM" sweep "$SCENE" --param 'joint[1].stiffness' --from 0 --to 400 --steps 100 \
  --param2 'joint[2].stiffness' --from2 0 --to2 400 --steps2 100 -o "$OUT/default-map.csv" || fail "chain-rom sweep"
"$PY" "$ROOT/scripts/plot_sweep.py" "$OUT/default-map.csv" -o "$OUT/default-map.png" \
  --title "default scene (water): growth rate over the joints' stiffnesses" --growth || fail "scripts/plot_sweep.py"

verdict=$(grep -m1 '^stable:' "$OUT/default-spectrum.txt" || true)
step "done in $((SECONDS - START)) s: $verdict"
echo "  outputs: out/tables/{cylinder,cone,spheroid}{_water,}.h5, out/default-spectrum.txt, out/default-ideal-spectrum.txt,"
echo "           out/default-trajectory.h5, out/default-trajectory.png, out/default-map.csv, out/default-map.png"
