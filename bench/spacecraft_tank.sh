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
