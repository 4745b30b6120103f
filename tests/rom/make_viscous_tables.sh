#!/usr/bin/env bash
# Viscous sphere tables (radius 1, spin-over mode) at Ek = 1e-3, 1e-4, 1e-5 for test_rom_viscous, written by
# cavity-modes itself (docs/viscous.md): the chain tests read what users' scenes read.
set -eu
BIN=$1
DST=$2
mkdir -p "$DST"
for ek in 1e-3 1e-4 1e-5; do
  "$BIN" sphere --radius 1 --ekman "$ek" --modes 1 --no-convergence-check -o "$DST/sphere_ek$ek.h5" > "$DST/sphere_ek$ek.txt"
done
echo "viscous sphere tables in $DST"
