#!/usr/bin/env bash
# chain-rom run with a Galerkin tank (docs/rom.md, "Galerkin tanks"): one spinning body with the fixture's viscous
# sphere table; the run prints H and its balance with the dissipation, and the CSV carries their columns. With
# reduction = "modal" the same run says why it has no H.
set -eu
ROM=$1
DIR=$2
cd "$DIR"
scene() {
  cat <<TOML
[system]
kind = "fixed"
gravity = 0.0
[[body]]
mass = 0.5
A = 0.002
C = 0.004
com = 0.0
spin = 100.0
[body.cavity]
table = "sphere_ek1e-3.h5"
viscosity = 2.5e-4
density = 1000.0
scale = 0.05
center = 0.0
reduction = "$1"
[initial]
tilt = [[0.01, 0.0]]
rate = [[0.0, 0.5]]
[run]
t_end = 1.0
output_step = 0.001
TOML
}
scene galerkin > galerkin_cli.toml
out=$("$ROM" run galerkin_cli.toml -o galerkin_cli.csv)
echo "$out"
echo "$out" | grep -q 'energy: H(0) = .*dissipated .* J (fluid .* J); dH/dt = -(joint power + fluid dissipation) to'
head -1 galerkin_cli.csv | grep -q ',energy,joint_power,fluid_dissipation,dissipated$'
scene modal > modal_cli.toml
out=$("$ROM" run modal_cli.toml -o modal_cli.csv)
echo "$out"
echo "$out" | grep -q 'energy: no integral with these viscous tanks: body 1.s tank is a modal viscous tank'
rm -f galerkin_cli.toml galerkin_cli.csv modal_cli.toml modal_cli.csv
echo "galerkin run: ok"
