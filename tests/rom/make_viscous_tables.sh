#!/usr/bin/env bash
# Viscous tables for test_rom_viscous: the sphere (radius 1, spin-over mode) at Ek = 1e-3, 1e-4, 1e-5 and the
# cylinder's four leading damped modes at Ek = 1e-3, the sphere's Galerkin response table, written by cavity-modes itself (docs/viscous.md): the chain tests read what users' scenes read.
set -eu
BIN=$1
DST=$2
mkdir -p "$DST"
for ek in 1e-3 1e-4 1e-5; do
  "$BIN" sphere --radius 1 --ekman "$ek" --modes 1 --no-convergence-check -o "$DST/sphere_ek$ek.h5" > "$DST/sphere_ek$ek.txt"
done
# Four damped modes of the cylinder (radius 1, height 2) at Ek = 1e-3 with their Galerkin matrices, for the
# Galerkin tanks' tests (test_galerkin_tanks.cpp).
"$BIN" cylinder --radius 1 --height 2 --ekman 1e-3 --modes 4 --no-convergence-check -o "$DST/cylinder_ek1e-3.h5" \
  > "$DST/cylinder_ek1e-3.txt"
# The sphere's Galerkin response table (P3, 41 samples of [-1.5, 2]): pseudo-modes whose fluid keeps an energy.
"$BIN" response sphere --radius 1 --ekman 1e-3 --order 3 --sigma -1.5:2:41 --galerkin -o "$DST/sphere_galerkin_ek1e-3.h5" \
  > "$DST/sphere_galerkin_ek1e-3.txt"
# The sphere filled to 0.4 (a free surface), ideal and at Ek = 1e-3 (two damped modes), for the chain without axial
# symmetry's partially filled tank (test_viscous_chain.cpp).
"$BIN" sphere --radius 1 --fill 0.4 -o "$DST/sphere_fill0.4.h5" > "$DST/sphere_fill0.4.txt"
# (P3, h 0.25: its tests compare two chains on the one table, 8 s against 13 s at the default P6)
"$BIN" sphere --radius 1 --fill 0.4 --ekman 1e-3 --modes 2 --no-convergence-check --order 3 --mesh-size 0.25 \
  -o "$DST/sphere_fill0.4_ek1e-3.h5" \
  > "$DST/sphere_fill0.4_ek1e-3.txt"
echo "viscous tables in $DST"
