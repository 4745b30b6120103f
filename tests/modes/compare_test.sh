#!/usr/bin/env bash
# `cavity-modes compare` against the shipped closed-form reference tables (data/reference/):
# default-order tables of two spheroids and the 2h/a = 2 cylinder must pass at 1e-6; a reference row
# that is off, mismatched dimensions and malformed CSVs must fail with one line on stderr naming the cause.
set -u
source "$(cd "$(dirname "$0")" && pwd)/cli_checks.sh"
BIN=$1
REF=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

expect_pass() {  # name, command...
  local name=$1
  shift
  if "$@" > stdout.txt 2> stderr.txt && [ ! -s stderr.txt ]; then
    ok "$name: $(grep '^worst' stdout.txt)"
  else
    bad "$name: $(cat stdout.txt stderr.txt)"
  fi
}

"$BIN" compare --help > help.txt 2>&1 && grep -q tolerance help.txt && ok "compare --help" || bad "compare --help"

# Tables at the default settings (spheroids: mesh method; cylinder: separable); the cylinder keeps the 8 modes of
# largest E.
"$BIN" spheroid --a 1 --c 0.5 -o oblate.h5 > /dev/null 2>&1 || bad "oblate spheroid table"
"$BIN" spheroid --a 1 --c 2 -o prolate.h5 > /dev/null 2>&1 || bad "prolate spheroid table"
"$BIN" cylinder --radius 1 --height 2 --modes 8 -o cyl.h5 > /dev/null 2>&1 || bad "cylinder table"

expect_pass "oblate spheroid vs reference" "$BIN" compare oblate.h5 "$REF/spheroid_a1_c0.5.csv"
expect_pass "prolate spheroid vs reference" "$BIN" compare prolate.h5 "$REF/spheroid_a1_c2.csv"
# The annular cylinder (a section with no axis) by the mesh method against its separable closed form.
"$BIN" section "$REF/../sections/annulus.geo" --modes 8 -o annulus.h5 > /dev/null 2>&1 || bad "annulus table"
expect_pass "annular cylinder section vs its closed form (8 modes, 1e-5: the 7th mode's E is 1.2e-6 off on the default mesh)" "$BIN" compare annulus.h5 "$REF/section_annulus.csv" --tolerance 1e-5
"$BIN" cylinder --radius 1 --height 2 --inner-radius 0.3 --modes 8 -o ring.h5 > /dev/null 2>&1 || bad "annular cylinder table"
expect_pass "cylinder --inner-radius 0.3 (separable, the default) vs its closed form (8 modes, 1e-9)" "$BIN" compare ring.h5 "$REF/cylinder_radius1_height2_inner0.3.csv" --tolerance 1e-9
"$BIN" cylinder --radius 1 --height 2 --inner-radius 0.3 --method mesh --modes 8 -o ring_mesh.h5 > /dev/null 2>&1 || bad "annular cylinder table (mesh)"
expect_pass "cylinder --inner-radius 0.3 --method mesh vs its closed form (8 modes, 1e-5)" "$BIN" compare ring_mesh.h5 "$REF/cylinder_radius1_height2_inner0.3.csv" --tolerance 1e-5
expect_error "an annular table against the full cylinder's reference" "dimension 'inner_radius'" "$BIN" compare ring.h5 "$REF/cylinder_radius1_height2.csv"
expect_pass "cylinder 2h/a = 2 vs Stewartson (8 modes)" "$BIN" compare cyl.h5 "$REF/cylinder_radius1_height2.csv"
cp stdout.txt cyl-compare.txt
cat cyl-compare.txt
if [ "$(grep -c 'n=0\|n=1' cyl-compare.txt)" -eq 8 ] && grep -q '8 of 8 rows within 1e-06' cyl-compare.txt; then
  ok "report lists all 8 rows"
else
  bad "report lists all 8 rows"
fi
# The separable table agrees with Stewartson to ~7e-13 (docs/reference-tables.md); 1e-14 is tighter than that.
expect_error "tolerance tighter than the discretisation" "worst: row" \
  "$BIN" compare cyl.h5 "$REF/cylinder_radius1_height2.csv" --tolerance 1e-14

# One E off by 1e-4 relative (row 3, line 8 of the file): the message names the row.
python3 - "$REF/cylinder_radius1_height2.csv" perturbed.csv <<'EOF'
import sys
lines = open(sys.argv[1]).read().splitlines(keepends=True)
data = [i for i, l in enumerate(lines) if l.strip() and not l.startswith("#")][1:]
i = data[2]
f = lines[i].split(",")
f[3] = repr(float(f[3]) * (1 + 1e-4))
lines[i] = ",".join(f)
open(sys.argv[2], "w").write("".join(lines))
EOF
expect_error "one E off by 1e-4" "worst: row 3 (perturbed.csv line 8, kappa -3.18545" "$BIN" compare cyl.h5 perturbed.csv
grep -q "E differs from cluster 3 by -1.00e-04" stderr.txt && ok "message gives the difference" \
  || bad "message gives the difference: $(cat stderr.txt)"

# Shape and dimensions must match the table's (each dimension within 1e-12 relative).
expect_error "other aspect ratio" "height = 4 does not match the table's height = 2" \
  "$BIN" compare cyl.h5 "$REF/cylinder_radius1_height4.csv"
expect_error "other shape" "shape 'cylinder' does not match the table's 'spheroid'" \
  "$BIN" compare oblate.h5 "$REF/cylinder_radius1_height2.csv"
sed 's/height=2;/height=2.000000001;/' "$REF/cylinder_radius1_height2.csv" > near.csv
expect_error "dimension off by 5e-10" "does not match" "$BIN" compare cyl.h5 near.csv
sed 's/height=2;/height=2.0000000000000004;/' "$REF/cylinder_radius1_height2.csv" > ulp.csv
expect_pass "dimension off by one ulp" "$BIN" compare cyl.h5 ulp.csv
sed 's/height=2;radius=1/radius=1/' "$REF/cylinder_radius1_height2.csv" > nodim.csv
expect_error "dimension missing" "dimension 'height' missing" "$BIN" compare cyl.h5 nodim.csv
sed 's/height=2;/depth=2;/' "$REF/cylinder_radius1_height2.csv" > otherdim.csv
expect_error "unknown dimension" "dimension 'depth' is not one of the table's" "$BIN" compare cyl.h5 otherdim.csv

# Malformed CSVs.
good='spheroid,a=1;c=0.5,1.25,0.33510321638291124,"Poincare, closed form",x'
printf 'shape,dimensions,kappa,source\nspheroid,a=1;c=0.5,1.25,src\n' > nocol.csv
expect_error "missing column" "lacks column 'E'" "$BIN" compare oblate.h5 nocol.csv
printf 'shape,dimensions,kappa,E,source,label\n%s\nspheroid,a=1;c=0.5,1.25,abc,src,x\n' "$good" > text.csv
expect_error "non-numeric E" "line 3: E = 'abc' is not a number" "$BIN" compare oblate.h5 text.csv
printf 'shape,dimensions,kappa,E,source\nspheroid,a=1;c=0.5,nan,0.3,src\n' > nan.csv
expect_error "NaN kappa" "kappa = 'nan' is not finite" "$BIN" compare oblate.h5 nan.csv
printf 'shape,dimensions,kappa,E,source\nspheroid,a=1;c=NaN,1.25,0.3,src\n' > nandim.csv
expect_error "NaN dimension" "dimension c = 'NaN' is not finite" "$BIN" compare oblate.h5 nandim.csv
printf 'shape,dimensions,kappa,E,source\nspheroid,a=1;c=0.5,1.25,,src\n' > blank.csv
expect_error "empty E" "E is empty" "$BIN" compare oblate.h5 blank.csv
printf 'shape,dimensions,kappa,E,source\nspheroid,a=1;c=0.5,1.25,0.3\n' > short.csv
expect_error "missing field" "4 fields, the header has 5 columns" "$BIN" compare oblate.h5 short.csv
printf 'shape,dimensions,kappa,E,source\nspheroid,a=1;c=0.5,1.25,0.3,"unterminated\n' > quote.csv
expect_error "unterminated quote" "unterminated quote" "$BIN" compare oblate.h5 quote.csv
printf 'shape,dimensions,kappa,E,source,Kappa\n' > unknown.csv
expect_error "unknown column" "unknown column 'Kappa'" "$BIN" compare oblate.h5 unknown.csv
: > empty.csv
expect_error "empty CSV" "empty" "$BIN" compare oblate.h5 empty.csv
printf '# only a comment\nshape,dimensions,kappa,E,source\n\n' > header-only.csv
expect_error "header without rows" "no reference rows" "$BIN" compare oblate.h5 header-only.csv
expect_error "missing CSV" "cannot read" "$BIN" compare oblate.h5 none.csv
expect_error "table is not HDF5" "not an HDF5 file" "$BIN" compare empty.csv "$REF/spheroid_a1_c0.5.csv"
expect_error "bad tolerance" "tolerance" "$BIN" compare oblate.h5 "$REF/spheroid_a1_c0.5.csv" --tolerance -1
# Comments, blank lines, column order and quoting are free.
printf '# c\n\nE,kappa,"source",shape,dimensions\n0.33510321638291124, 1.25 ,"a ""quoted"", source",spheroid,c=0.5; a=1\n' \
  > reordered.csv
expect_pass "reordered columns and quoting" "$BIN" compare oblate.h5 reordered.csv

finish
