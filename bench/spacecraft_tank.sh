#!/usr/bin/env bash
# Sourced by the bench scripts that put one tank into the spacecraft of data/scenes/spacecraft_nutation.toml (800 kg,
# A = 400, C = 520 kg m^2, 60 rpm; the tank's scale 0.4 m, its centre 0.3 m above the centre of mass): timing helpers
# and the scene itself, for a tank table and an Ekman number; and OpenBLAS's kernels chosen from the CPU's flags
# (scripts/blas-core.sh), as the test and run scripts choose them.
#   source bench/spacecraft_tank.sh; spacecraft_tank_scene EKMAN TABLE.h5 > scene.toml
# shellcheck source=../scripts/blas-core.sh
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/scripts/blas-core.sh"
now() { date +%s.%N; }
# Seconds since a `now`, rounded to two decimals.
since() { python3 -c "print(round($(now) - $1, 2))"; }
# The scene with TABLE as its tank and the viscosity nu = Ek |spin| scale^2 that makes the table's Ekman number.
spacecraft_tank_scene() {
  local root nu
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  nu=$(python3 -c "print($1 * 6.2832 * 0.16)")
  sed -e "s#\"../../out/tables/sphere_fill0.6_hydrazine.h5\"#\"$2\"#" -e "s#^viscosity = .*#viscosity = $nu#" \
    "$root/data/scenes/spacecraft_nutation.toml"
}
# The tank's default response table, the recipe of docs/trust.md's rows: SHAPE_ARGS as one string (e.g. "sphere
# --radius 1"), FILL (1: full), EKMAN, the table file, then any further options of `cavity-modes response`.
#   spacecraft_tank_table MODES SHAPE_ARGS FILL EKMAN TABLE.h5 [OPTIONS...] > table.txt 2>&1
spacecraft_tank_table() {
  local modes=$1 shape_line=$2 fill=$3 ek=$4 table=$5
  shift 5
  local shape fill_args=()
  read -r -a shape <<< "$shape_line"
  [ "$fill" = 1 ] || fill_args=(--fill "$fill")
  "$modes" response "${shape[@]}" "${fill_args[@]}" --ekman "$ek" --sigma -2.5:2:181 "$@" -o "$table"
}
# The run's folders: OUT (the results, read from the caller) made and made absolute, and a work folder, removed at
# exit, entered, holding the scene for EKMAN with tank.h5 as its table.
#   spacecraft_tank_workdir EKMAN
spacecraft_tank_workdir() {
  mkdir -p "$OUT"
  OUT=$(cd "$OUT" && pwd)
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  cd "$work"
  spacecraft_tank_scene "$1" tank.h5 > scene.toml
}
