#!/usr/bin/env bash
# Command-line behaviour of cavity-modes: help, a good run with info --json, and every bad-input case
# giving a one-line error, a non-zero exit and no file left behind.
set -u
source "$(cd "$(dirname "$0")" && pwd)/cli_checks.sh"
BIN=$1
SECTIONS=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

"$BIN" --help > help.txt 2>&1 && grep -q cylinder help.txt && ok "--help" || bad "--help"

expect_error "unknown shape" "unknown shape" "$BIN" torus --radius 1 -o out.h5
expect_error "zero radius" "radius = 0" "$BIN" sphere --radius 0 -o out.h5
expect_error "negative height" "height = -2" "$BIN" cylinder --radius 1 --height -2 -o out.h5
expect_error "NaN dimension" "nan" "$BIN" spheroid --a nan --c 1 -o out.h5
expect_error "missing dimension" "--c" "$BIN" spheroid --a 1 -o out.h5
expect_error "loose convergence tolerance" "convergence-tolerance must be in" "$BIN" cone --radius 1 --height 1 --convergence-tolerance 1e-2 -o out.h5
expect_error "unreadable section" "cannot read" "$BIN" section "$work/none.geo" -o out.h5
echo 'Point(1) = {0, 0, 0};' > nogroups.geo
expect_error "section without physical groups" "fluid" "$BIN" section nogroups.geo -o out.h5
echo 'garbage(' > broken.geo
expect_error "malformed section" "syntax error" "$BIN" section broken.geo -o out.h5
expect_error "bad coverage" "coverage" "$BIN" sphere --radius 1 --coverage 2 -o out.h5
expect_error "solver failure (slices)" "eigensolver" "$BIN" sphere --radius 1 --order 3 --clusters slices -o out.h5 -pep_max_it 1 -pep_tol 1e-30
expect_error "solver failure (lanczos, then its slice fallback)" "eigensolver" "$BIN" sphere --radius 1 --order 3 --lanczos-steps 2 -o out.h5 -pep_max_it 1 -pep_tol 1e-30
expect_error "Q(sigma) solve failure" "factorisation of Q(sigma)" "$BIN" sphere --radius 1 --order 3 -o out.h5 -shift_ksp_type cg -shift_pc_type none -shift_ksp_max_it 1
expect_error "unwritable output" "cannot create" "$BIN" sphere --radius 1 --order 3 -o /nonexistent-dir/out.h5
expect_error "info on a non-table" "not an HDF5 file" "$BIN" info stderr.txt
# --method separable (cylinders only; docs/modes.md "Separable cylinder solver")
expect_error "separable for a sphere" "sphere does not take --method" "$BIN" sphere --radius 1 --method separable -o out.h5
# Each shape's --help lists only what it takes, without CLI11's internal value maps; what it does not take is refused.
"$BIN" sphere --help > sphere_help.txt 2>&1
if grep -q -- "--radius" sphere_help.txt && ! grep -q -- "--radial-size\|--method\|--sigma\|ENUM\|[a-z]->[0-9]" sphere_help.txt; then
  ok "sphere --help lists only the sphere's options"
else
  bad "sphere --help: $(grep -- '--radial-size\|--method\|--sigma\|ENUM\|[a-z]->[0-9]' sphere_help.txt | head -2)"
fi
"$BIN" response cylinder --help > response_help.txt 2>&1
if grep -q "^Usage: .*cavity-modes response cylinder" response_help.txt && grep -q -- "--sigma" response_help.txt && grep -q -- "--method" response_help.txt && ! grep -q -- "^  --modes\|^  --fields" response_help.txt; then
  ok "response cylinder --help lists the response's options"
else
  bad "response cylinder --help"
fi
expect_error "radial size for a sphere" "sphere does not take --radial-size" "$BIN" sphere --radius 1 --radial-size 0.1 -o out.h5
expect_error "table option on a response" "response sphere does not take --modes" "$BIN" response sphere --radius 1 --modes 2 --sigma 0.5+0.1i -o out.csv
expect_error "empty option value" "an empty value after --coverage" "$BIN" sphere --radius 1 --coverage "" -o out.h5
expect_error "empty option value (=)" "an empty value for --mesh-size" "$BIN" sphere --radius 1 --mesh-size= -o out.h5
expect_error "misspelt option" "does not take --mesh-sise" "$BIN" cone --radius 1 --height 1 --mesh-sise 0.1 -o out.h5
expect_error "separable with --fields" "--fields needs --method mesh" "$BIN" cylinder --radius 1 --height 2 --method separable --fields -o out.h5
expect_error "rod as wide as the cylinder" "must be below the radius" "$BIN" cylinder --radius 1 --height 2 --inner-radius 1 -o out.h5
expect_error "--inner-radius on a cone" "cone does not take --inner-radius" "$BIN" cone --radius 1 --height 1 --inner-radius 0.3 -o out.h5
expect_error "separable order out of range" "order 13 is outside 1..12" "$BIN" cylinder --radius 1 --height 2 --order 13 -o out.h5
expect_error "mesh-only option with separable" "--clusters applies to --method mesh" "$BIN" cylinder --radius 1 --height 2 --clusters slices -o out.h5
expect_error "separable negative radial size" "must be positive" "$BIN" cylinder --radius 1 --height 2 --radial-size -0.1 -o out.h5
expect_error "unknown method" "--method" "$BIN" cylinder --radius 1 --height 2 --method fancy -o out.h5
expect_error "separable grid too large for the dense solver" "exceed what the dense solver handles" "$BIN" cylinder --radius 1 --height 1 --radial-size 0.005 -o out.h5
if "$BIN" cylinder --radius 1 --height 2 --modes 3 -o sep.h5 > sep.txt 2>&1 && "$BIN" info sep.h5 --json > sep.json &&
   python3 -c '
import json
j = json.load(open("sep.json"))
assert j["solver"].startswith("separable"), j["solver"]
assert len(j["modes"]["E"]) == 3 and abs(j["modes"]["kappa"][0] - 2.0089710942) < 1e-8, j["modes"]["kappa"]
'; then ok "cylinder table by the separable method (default)"; else bad "separable cylinder table: $(tail -2 sep.txt)"; fi

# A good run, its table, and info --json (parsed by Python's json module).
if "$BIN" spheroid --a 1 --c 0.5 --order 4 -o good.h5 > run.txt 2>&1 && [ -f good.h5 ]; then
  ok "spheroid table written"
  if "$BIN" info good.h5 --json > info.json && python3 -c '
import json, sys
j = json.load(open("info.json"))
assert j["format"] == "cavity-mode-table" and j["shape"] == "spheroid"
for k in ("kappa", "lambda", "E", "a", "N2", "residual"):
    assert len(j["modes"][k]) == len(j["modes"]["E"]) >= 1, k
E = j["modes"]["E"]
assert E == sorted(E, reverse=True)
err = abs(j["modes"]["lambda"][0] - 1.6) / 1.6
print("info --json: lambda_1 rel err %.2e" % err)
assert err < 1e-8
'; then ok "info --json"; else bad "info --json"; fi
else
  bad "spheroid table written: $(cat run.txt)"
fi
# A user section (the capsule example) runs end to end.
if "$BIN" section "$SECTIONS/capsule.geo" --order 4 --modes 3 -o capsule.h5 > cap.txt 2>&1 && [ -f capsule.h5 ]; then
  ok "capsule section"
  # The table keeps its section's text and command line; info shows them and gives the text back unchanged.
  "$BIN" info capsule.h5 > cap_info.txt 2>&1
  if grep -q "^geometry: .*capsule.geo (its text, 26 lines" cap_info.txt && grep -q "^made by: .* section .*capsule.geo --order 4 --modes 3 -o capsule.h5" cap_info.txt &&
     "$BIN" info capsule.h5 --geometry | cmp -s - "$SECTIONS/capsule.geo"; then
    ok "table records its section file and command line"
  else
    bad "provenance: $(grep '^geometry\|^made by' cap_info.txt)"
  fi
  # Unconverged clusters: one plain line at the end of the run and of info, naming what does converge.
  if grep -q "^note: 3 of 3 clusters did not converge.*J_zh, A_f, A_f - J_zh and the band weights.*docs/trust.md" cap.txt &&
     grep -q "^note: 3 of 3 clusters did not converge" cap_info.txt; then
    ok "note on unconverged clusters"
  else
    bad "note on unconverged clusters: $(tail -1 cap.txt)"
  fi
  # compare, table against table: the same table agrees in every digit; another cavity is refused.
  if "$BIN" compare capsule.h5 capsule.h5 > self.txt 2>&1 && grep -q "^ *J_zh .* 16$" self.txt &&
     grep -q "within 1e-06" self.txt; then ok "compare: a table against itself"; else bad "compare itself: $(tail -2 self.txt)"; fi
  # A section's own CSV (dimensions empty): its dominant cluster, to the printed digits.
  kappa=$("$BIN" info capsule.h5 --json | python3 -c 'import json,sys; j=json.load(sys.stdin); print("%.15g,%.15g" % (j["modes"]["kappa"][0], j["modes"]["E"][0]))')
  printf 'shape,dimensions,kappa,E,source\nsection,,%s,this test\n' "$kappa" > cap_ref.csv
  if "$BIN" compare capsule.h5 cap_ref.csv > cap_cmp.txt 2>&1 && grep -q "made from .*capsule.geo" cap_cmp.txt; then
    ok "compare: a section table against a CSV"
  else
    bad "compare section against CSV: $(tail -2 cap_cmp.txt)"
  fi
else
  bad "capsule section: $(tail -1 cap.txt)"
fi

# spectral-window takes every shape with cavity-modes' mesh options. Sphere: its one coupling mode (lambda = 1)
# carries the whole sum rule A_f - J_zh, so the window around it holds all of it and the rest hold nothing.
SW=$(dirname "$BIN")/spectral-window
if "$SW" sphere --radius 1 --order 6 --window 0.9,1.1 --window 0.3,0.6 > sw.json 2> sw.err && python3 -c '
import json
rows = [json.loads(l) for l in open("sw.json")]
err = abs(rows[0]["E"] - rows[0]["sum_rule"]) / rows[0]["sum_rule"]
print("spectral-window sphere: E in [0.9, 1.1) against A_f - J_zh: rel err %.2e; E in [0.3, 0.6): %.2e" % (err, rows[1]["E"]))
assert err < 1e-10 and rows[1]["E"] < 1e-10 * rows[0]["sum_rule"]
'; then ok "spectral-window sphere"; else bad "spectral-window sphere: $(tail -1 sw.err)"; fi
if "$SW" section "$SECTIONS/capsule.geo" --order 3 --mesh-size 0.5 --window 0.4,0.5 > swc.json 2> swc.err &&
   grep -q '"pairs":6' swc.json; then ok "spectral-window section"; else bad "spectral-window section: $(cat swc.json swc.err | tail -1)"; fi
expect_error "spectral-window bad window" "expected LO,HI" "$SW" sphere --radius 1 --window 0.5 
expect_error "spectral-window option of another shape" "radial-size" "$SW" sphere --radius 1 --radial-size 0.1 --window 0.1,0.2

# More modes asked than the cavity has: the table holds what exists, and one line says so.
if "$BIN" sphere --radius 1 --order 3 --modes 3 --no-convergence-check -o few.h5 > few.txt 2> few.err &&
   grep -q "modes 3 asked, the table holds 1" few.err && [ "$(wc -l < few.err)" -eq 1 ]; then
  ok "fewer modes than --modes: $(cat few.err)"
else
  bad "fewer modes than --modes: $(cat few.err)"
fi

# Edited and corrupted tables: refused on reading with one line naming what is wrong, fast.
if "$BIN" sphere --radius 1 --order 3 --mesh-size 0.5 -o base.h5 > /dev/null 2>&1 && /usr/bin/python3 -c '
import h5py, shutil
def variant(name, edit):
    shutil.copy("base.h5", name)
    with h5py.File(name, "a") as f:
        edit(f)
variant("no_dlambda.h5", lambda f: f["modes"].__delitem__("dlambda"))
variant("lambda0.h5", lambda f: f["modes/lambda"].__setitem__(0, 0.0))
variant("kappa.h5", lambda f: f["modes/kappa"].__setitem__(0, 3.0))
variant("negN2.h5", lambda f: f["modes/N2"].__setitem__(0, -1.0))
variant("nega.h5", lambda f: f["modes/a"].__setitem__(0, -f["modes/a"][0]))
def huge(f):  # a size the file cannot hold: two billion entries, none stored
    del f["modes/E"]
    f["modes"].create_dataset("E", shape=(2 * 10**9,), dtype="f8", chunks=(1024,))
variant("huge.h5", huge)
'; then
  expect_error "table without /modes/dlambda" "come together" timeout 10 "$BIN" info no_dlambda.h5
  expect_error "table with lambda = 0" "lambda != 0" timeout 10 "$BIN" info lambda0.h5
  expect_error "table with kappa not 2/lambda" "kappa = 2/lambda" timeout 10 "$BIN" info kappa.h5
  expect_error "table with N2 < 0" "N2 > 0" timeout 10 "$BIN" info negN2.h5
  expect_error "table with a < 0" "a >= 0" timeout 10 "$BIN" info nega.h5
  expect_error "table claiming 2e9 entries" "more than the file holds" timeout 10 "$BIN" info huge.h5
  [ -f capsule.h5 ] && expect_error "compare two cavities" "describe different cavities: a section and a sphere" "$BIN" compare capsule.h5 base.h5
  # Bytes that are not UTF-8 in a string attribute print as \xNN escapes (text and JSON).
  /usr/bin/python3 -c '
import h5py, numpy as np, shutil
shutil.copy("base.h5", "bytes.h5")
with h5py.File("bytes.h5", "a") as f:
    del f.attrs["solver"]
    f.attrs.create("solver", np.bytes_(b"lanczos \xff\xfe\x07 end"))
'
  if "$BIN" info bytes.h5 > bytes.txt 2>&1 && "$BIN" info bytes.h5 --json > bytes.json 2>&1 &&
     /usr/bin/python3 -c '
import json
t = open("bytes.txt", "rb").read().decode("utf-8")  # fails on raw bytes
assert "lanczos \\xFF\\xFE\\x07 end" in t, t
assert json.load(open("bytes.json"))["solver"] == "lanczos \\xFF\\xFE\\x07 end"
'; then ok "non-UTF-8 bytes in a table print escaped"; else bad "non-UTF-8 bytes: $(head -c 300 bytes.txt)"; fi
else
  bad "could not make the edited tables"
fi

finish
