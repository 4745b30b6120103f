#!/usr/bin/python3
"""A partially filled tank's 3-D viscous response table in the chain without axial symmetry (docs/volume.md §8, "The
viscous liquid").

A sphere filled to 0.6 on the spin axis of a body on a fixed joint (80 kg, A 12, C 10 kg m², spin 30 rad/s, the tank
0.2 m in radius, 1004 kg/m³, nu 0.012 m²/s: Ek = 1e-2), its response table made twice by independent discretisations:
the meridian solver's Krylov table (cavity-modes response sphere --fill: P6 triangles, m = 1) into Kononov's (26), and
the 3-D one (cavity-modes ellipsoid --fill --ekman --sigma ... -o T.h5: P2 tetrahedra, h 0.3, refined towards the
contact lines, five directions) into
the general chain. Compared in the turning frame (sigma + spin for (26)'s):
1. the body's nutation frequency and its growth rate (the liquid destabilises this prolate body), the tank's centroid
   at the joint's height and 0.3 tank radii above it (the offset directions and the re-centring inertia K(O) too);
2. refused in one line: the 3-D viscous fill table on a body spinning the other way (its mirror image is another
   liquid);
2b. the free chain (docs/volume.md §8, "The free chain"): the c = 0.3 body in free flight, (26)'s free chain against
   the general chain whose base recoils with the liquid; the root's move from the fixed chain in both;
3. with PART = confirm instead: `chain-rom confirm --refine-tables` on the c = 0 scene remakes the 3-D table from its
   own command line exact at the root (which moves by the table's fit error only) and again on a mesh 1.5 times as
   coarse; its growth rate's error bar must cover the growth's true error against (26), and the verdict line must say
   NOT CONVERGED exactly when that bar exceeds its 2 % tolerance.
usage: viscous_fill_3d_check.py CAVITY_MODES CHAIN_ROM WORKDIR [tables|chain|confirm]
PART = tables makes the two tables in WORKDIR (about 28 s), which the other parts read: ctest runs it once as the
fixture of both.
"""
import json, os, subprocess, sys

modes_bin, rom_bin, work = sys.argv[1:4]
part = sys.argv[4] if len(sys.argv) > 4 else "chain"
os.makedirs(work, exist_ok=True)
os.chdir(work)
failures = []

def run(*args):
    p = subprocess.run(list(args), capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("failed: " + " ".join(args) + "\n" + p.stderr[-2000:])
    return p.stdout

EK = "1e-2"
if part == "tables":
    for f in ("meridian.h5", "volume.h5"):
        if os.path.exists(f): os.remove(f)  # a table of an earlier build is not this one's
    run(modes_bin, "response", "sphere", "--radius", "1", "--fill", "0.6", "--ekman", EK, "--sigma", "-3:3:61",
        "-o", "meridian.h5")
    run(modes_bin, "ellipsoid", "--a", "1", "--b", "1", "--c", "1", "--fill", "0.6", "--ekman", EK, "--order", "2",
        "--mesh-size", "0.3", "--sigma", "0:3:31", "-o", "volume.h5")
    print("the meridian and the 3-D tables made")
    sys.exit(0)
for f in ("meridian.h5", "volume.h5"):
    if not os.path.exists(f): sys.exit("no %s in %s: run the part `tables` first" % (f, work))

SPIN = 30.0
def scene(table, center, spin=SPIN, kind="fixed"):
    name = "%s_%s_%g_%g_%s.toml" % (part, table.split(".")[0], center, spin, kind)  # the parts run side by side
    with open(name, "w") as f:
        f.write('[system]\nkind = "%s"\ngravity = 0\n' % kind + '[[body]]\nmass = 80.0\nA = 12.0\nC = 10.0\ncom = 0.05\n'
                'spin = %g\n[body.cavity]\ntable = "%s"\ndensity = 1004.0\nscale = 0.2\ncenter = %g\n'
                'viscosity = 0.012\n' % (spin, table, center))
    return name

def nutation(center, kind="fixed"):
    """The body's growing nutation root: (26)'s in space moved to the turning frame, and the general chain's nearest."""
    space = json.loads(run(rom_bin, "spectrum", scene("meridian.h5", center, kind=kind), "--json"))["roots"]
    # The body's root in space lies between -spin and 0; the fluid's there decay at least 30 times faster.
    body = sorted(((r[0] + SPIN, r[1]) for r in space if -SPIN + 1 < r[0] < -1), key=lambda r: abs(r[1]))[:1]
    if not body: sys.exit("no body root in (-spin, 0) of the axisymmetric chain")
    turning = json.loads(run(rom_bin, "spectrum", scene("volume.h5", center, kind=kind), "--json"))["roots"]
    general = min(turning, key=lambda r: abs(r[0] - body[0][0]) + abs(r[1] - body[0][1]))
    return body[0], (general[0], general[1])

# Measured 2026-12-07 (c = 0): P2 h 0.3 refined towards the contact lines (19 998 unknowns, 22 s) frequency 4.2e-4,
# growth 1.5 %; P3 h 0.45 so refined 3.9e-4 and 0.15 %; P3 h 0.3 1.7e-4 and 0.05 %. Without the contact lines'
# refinement P3 h 0.3 gave 1.5e-3 and 8 %, P4 h 0.3 1.1e-3 and 2.9 % (docs/volume.md §8). The meridian table at h 0.05
# moves its own root by 2e-5.
def confirm_part():
    """Part 3 (docstring). Measured 2026-12-07: growth 0.07024 +- 0.0024 1/s (3.5 %, NOT CONVERGED) against (26)'s
    0.071295 (1.5 % off: inside the bar); the root moved 1.1e-9; 63 s."""
    ref, got = nutation(0.0)
    p = subprocess.run([rom_bin, "confirm", scene("volume.h5", 0.0), "--refine-tables", "--cavity-modes", modes_bin,
                        "--json"], capture_output=True, text=True)
    if p.returncode != 0: sys.exit("confirm failed:\n" + p.stderr[-2000:])
    c = json.loads(p.stdout.strip().splitlines()[-1])
    # The nutation as a real motion is the pair +-Re sigma: either root of it.
    root = min(c["roots"], key=lambda r: abs(abs(r["confirmed"][0]) - abs(got[0])) + abs(r["confirmed"][1] - got[1]))
    growth, bar = root["growth"], root["growth_error"]
    true_error = abs(growth - (-ref[1]))
    moved = abs(complex(*root["confirmed"]) - complex(*root["table"])) / abs(complex(*root["table"]))
    print("confirm: growth %.6f +- %.2g 1/s (%.1f %%), %s; (26)'s %.6f: off by %.2g (%.1f bars); the root moved %.1e"
          % (growth, bar, 100 * bar / growth, "converged" if root["mesh_converged"] else "NOT CONVERGED", -ref[1],
             true_error, true_error / bar, moved))
    if not true_error <= bar: failures.append("the error bar %.2g does not cover the true error %.2g" % (bar, true_error))
    if root["mesh_converged"] != (bar <= 0.02 * growth):
        failures.append("the verdict's convergence (%s) is not the bar's (%.1f %% against 2 %%)"
                        % (root["mesh_converged"], 100 * bar / growth))
    if not moved < 1e-5: failures.append("the confirmed root moved %.1e from the table's" % moved)
    if not abs(root["table"][1] - got[1]) < 1e-9 * abs(got[1]):
        failures.append("confirm's table root is not spectrum's")

if part == "confirm":
    confirm_part()
    print("FAILED: " + "; ".join(failures) if failures else "passed")
    sys.exit(1 if failures else 0)

moves = []
for center, tol_f, tol_g in ((0.0, 1e-3, 0.03), (0.06, 1e-3, 0.03)):
    ref, got = nutation(center)
    moves.append((ref, got))
    ef, eg = abs(got[0] - ref[0]) / abs(ref[0]), abs(got[1] - ref[1]) / abs(ref[1])
    print("c = %.1f: nutation (turning frame) (26) with the meridian table %.6f, growth %.6f 1/s; general chain with "
          "the 3-D table %.6f, growth %.6f 1/s: frequency %.1e, growth %.1e relative"
          % (center / 0.2, ref[0], -ref[1], got[0], -got[1], ef, eg))
    if not ref[1] < 0: failures.append("the reference nutation does not grow at c = %.1f" % (center / 0.2))
    if not ef < tol_f: failures.append("frequency at c = %.1f off by %.1e" % (center / 0.2, ef))
    if not eg < tol_g: failures.append("growth at c = %.1f off by %.1e" % (center / 0.2, eg))

# The root's move from c = 0 to 0.3, which the offset directions and K(O) carry (measured 2026-12-07: frequency 1.3e-3,
# growth 7.8e-4).
for i, what in ((0, "frequency"), (1, "growth")):
    ref_move, got_move = moves[1][0][i] - moves[0][0][i], moves[1][1][i] - moves[0][1][i]
    e = abs(got_move / ref_move - 1)
    print("the %s's move from c = 0 to 0.3: %.6f against %.6f (%.1e relative)" % (what, got_move, ref_move, e))
    if not e < 1e-2: failures.append("the %s's move differs by %.1e" % (what, e))

# The free chain at c = 0.3: the move from the fixed chain, which the base's recoil with the liquid carries (measured
# 2026-12-07: frequency 2.6e-4, growth 1.3e-3 of (26)'s move; the nutation itself 4.9e-4 and 1.6 %).
ref_free, got_free = nutation(0.06, kind="free")
for i, what in ((0, "frequency"), (1, "growth")):
    ref_move, got_move = ref_free[i] - moves[1][0][i], got_free[i] - moves[1][1][i]
    e = abs(got_move / ref_move - 1)
    print("free chain, c = 0.3: the %s's move from the fixed chain %.6f against (26)'s %.6f (%.1e relative)"
          % (what, got_move, ref_move, e))
    if not e < 1e-2: failures.append("the free chain's %s move differs by %.1e" % (what, e))

p = subprocess.run([rom_bin, "spectrum", scene("volume.h5", 0.0, -SPIN)], capture_output=True, text=True)
lines = [l for l in p.stderr.splitlines() if l.strip()]
if p.returncode == 0 or len(lines) != 1 or "spin -w mirrors the cavity" not in lines[0]:
    failures.append("a 3-D viscous fill table on a body spinning the other way was not refused in one line: "
                    + p.stderr[-300:])
else:
    print("refused: " + lines[0][:160] + " ...")
print("FAILED: " + "; ".join(failures) if failures else "passed")
sys.exit(1 if failures else 0)
