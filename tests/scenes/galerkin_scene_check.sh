#!/usr/bin/env bash
# data/scenes/top_oil_galerkin.toml end to end: cavity-modes makes its table from the scene's "# recipe:" line
# (without the convergence check, to stay cheap), chain-rom runs the scene pointed at it, and the run must report H
# with its balance against the fluid's dissipation below 1e-8 on the samples (docs/rom.md, "Galerkin tanks").
set -eu
MODES=$1
ROM=$2
SCENE=$3
DIR=$4
rm -rf "$DIR" && mkdir -p "$DIR" && cd "$DIR"
recipe=$(sed -n 's/^# recipe: \([^:]*\): \(.*\)$/\1|\2/p' "$SCENE")
name=${recipe%%|*}
args=${recipe#*|}
# shellcheck disable=SC2086  # the recipe's arguments are words
"$MODES" $args --no-convergence-check -o "$name" > table.txt
sed "s#\"../../out/tables/$name\"#\"$name\"#" "$SCENE" > scene.toml
out=$("$ROM" run scene.toml -o run.csv 2>&1)
echo "$out"
line=$(echo "$out" | grep 'energy: H(0) = .*dH/dt = -(joint power + fluid dissipation) to ')
residual=${line##* to }
residual=${residual%% *}
awk -v r="$residual" 'BEGIN { exit !(r < 1e-8) }' || { echo "balance residual $residual >= 1e-8"; exit 1; }
echo "ok: balance residual $residual"
