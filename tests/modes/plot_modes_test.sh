#!/usr/bin/env bash
# scripts/plot_modes.py: draws a table with fields and one without, refuses a bad --mode with one line.
# Skipped (exit 77) where Debian's matplotlib is missing.
set -u
source "$(cd "$(dirname "$0")" && pwd)/cli_checks.sh"
BIN=$1
PLOT=$2
/usr/bin/python3 -c 'import matplotlib, h5py' 2> /dev/null || { echo "matplotlib or h5py missing: skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

png_ok() {  # file: exists, non-empty, PNG signature
  [ -s "$1" ] && [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]
}
"$BIN" cylinder --radius 1 --height 2 --order 3 --mesh-size 0.5 --modes 4 --fields -o f.h5 > run.txt 2>&1 \
  || bad "table with fields: $(tail -1 run.txt)"
"$BIN" sphere --radius 1 --order 2 --mesh-size 0.5 --no-convergence-check -o n.h5 > run.txt 2>&1 \
  || bad "table without fields: $(tail -1 run.txt)"
/usr/bin/python3 "$PLOT" f.h5 --mode 1 -o f.png && png_ok f.png && ok "clusters and mode 1's energy density ($(stat -c %s f.png) bytes)" \
  || bad "plot of a table with fields"
/usr/bin/python3 "$PLOT" n.h5 -o n.png && png_ok n.png && ok "clusters of a table without fields ($(stat -c %s n.png) bytes)" \
  || bad "plot of a table without fields"
expect_error "mode out of range" "outside the table's rows" /usr/bin/python3 "$PLOT" f.h5 --mode 99 -o out.h5
expect_error "--mode without fields" "no /fields" /usr/bin/python3 "$PLOT" n.h5 --mode 0 -o out.h5
expect_error "not a table" "not" /usr/bin/python3 "$PLOT" run.txt -o out.h5
finish
