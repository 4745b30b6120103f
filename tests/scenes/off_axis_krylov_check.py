#!/usr/bin/env python3
"""Viscous tanks off the spin axis with axisymmetric Krylov response tables, checked against (26).

  off_axis_krylov_check.py CAVITY_MODES CHAIN_ROM DIR

A spinning spacecraft (free, 800 kg, A 400, C 520 kg m^2, 1 rev/s) carries four identical spherical tanks, full, of
radius 0.3 m, their centres 0.6 m from the spin axis at 90 degrees from each other and 0.3 m above the craft's centre
of mass, with one axisymmetric Krylov response table of a sphere at Ek = 1e-4 (coarse: P3, h 0.4; the check is of the
chain, which agrees on any mesh). Offsets send the scene through the chain without axial symmetry (docs/rom.md,
"Bodies and tanks without axial symmetry"). A filled tank's relative flow does not depend on where it sits, and four
tanks at 90 degrees keep the craft's inertia axisymmetric, so the same craft is, for (26), one tank on the axis with
four times the density and the shell's A, C raised by the parallel-axis terms 2 m d^2, 4 m d^2 (m one tank's liquid).
Checked:
1. `spectrum`: every root of (26), turned into the turning frame (sigma + w and -(conj sigma + w)), is a root of the
   chain without axial symmetry to 1e-9 of the spectral radius, and every other root of it is a bare pole of the
   table (three of the four tanks' combinations do not couple to the craft) to 1e-9.
2. `confirm --refine-tables` on the four-tank scene against `confirm` of (26) (served forced solves on the same mesh):
   the confirmed roots agree to 1e-7 of the spin, and the mesh check's root on tables one level finer is (26)'s mesh
   study's level-1 root to 1e-6 of the spin; the growth rates' error bars agree to 1 %.
3. An axisymmetric response table whose window does not hold s = 0 is refused in one line that says what to make.
"""
import json, os, re, subprocess, sys

import h5py

modes, rom, out = sys.argv[1:4]
os.makedirs(out, exist_ok=True)
os.chdir(out)
EK, SPIN, L, D, H, RHO = 1e-4, 6.2832, 0.3, 0.6, 0.3, 1004.0
NU = EK * SPIN * L * L
table = ["response", "sphere", "--radius", "1", "--ekman", "1e-4", "--sigma", "-2.5:2:91", "--order", "3",
         "--mesh-size", "0.4"]
subprocess.run([modes] + table + ["-o", "sphere.h5"], check=True, stdout=subprocess.DEVNULL)
with h5py.File("sphere.h5") as f:
    volume = float(f.attrs["volume"])
m = RHO * L ** 3 * volume

HEAD = """[system]
kind = "free"

[[body]]
mass = 800.0
A = %r
C = %r
com = 0.0
spin = %r
"""
TANK = """[[body.cavity]]
table = "%s"
density = %r
scale = %r
center = %r
viscosity = %r
"""
def four_tanks(name, table_file):
    text = HEAD % (400.0, 520.0, SPIN)
    for x, y in [(D, 0), (-D, 0), (0, D), (0, -D)]:
        text += TANK % (table_file, RHO, L, H, NU) + "offset = [%r, %r]\n" % (float(x), float(y))
    open(name, "w").write(text)

def one_tank(name, table_file):
    open(name, "w").write(HEAD % (400.0 + 2 * m * D * D, 520.0 + 4 * m * D * D, SPIN) +
                          TANK % (table_file, 4 * RHO, L, H, NU))

def spectrum(scene):
    p = subprocess.run([rom, "spectrum", scene, "--json"], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("chain-rom spectrum %s: %s" % (scene, p.stderr))
    return json.loads(p.stdout)

def roots_of(j):
    return [complex(*r["sigma"]) if isinstance(r, dict) else complex(*r) for r in j["roots"]]

four_tanks("four.toml", "sphere.h5")
one_tank("one.toml", "sphere.h5")
general, axial = spectrum("four.toml"), spectrum("one.toml")
g_roots, a_roots = roots_of(general), roots_of(axial)
assert general.get("model") == "general", "the four-tank scene should go through the chain without axial symmetry"
radius = max(abs(r) for r in g_roots)
images = []
for s in a_roots:
    images += [s + SPIN, -(s.conjugate() + SPIN)]
worst = max(min(abs(g - x) for g in g_roots) for x in images) / radius
print("(26)'s %d roots turned into the turning frame: found among the %d of the four-tank chain to %.2e of the "
      "spectral radius" % (len(a_roots), len(g_roots), worst))
assert worst < 1e-9, "a root of (26) is not a root of the chain without axial symmetry"
with h5py.File("sphere.h5") as f:
    poles = [SPIN * complex(l, d) for l, d in zip(f["modes/lambda"][:], f["modes/decay"][:])]
poles += [-p.conjugate() for p in poles]
extra = 0
for g in g_roots:
    if min(abs(g - x) for x in images) <= 1e-9 * radius:
        continue
    extra += 1
    gap = min(abs(g - p) for p in poles) / radius
    assert gap < 1e-9, "a root %s of the four-tank chain is neither (26)'s nor a bare pole (%.2e)" % (g, gap)
print("its other %d roots are the table's bare poles (the tanks' uncoupled combinations)" % extra)
# Counted with multiplicity: (26)'s roots twice (sigma and its mirror) and three uncoupled copies of every pole and its
# mirror; a weakly coupled pole's root may sit within 1e-9 of its bare pole, so `extra` alone may count fewer.
# Both chains leave out the table's rows that no root needs (rom/model/response_row_pruning.hpp), the same rows: the
# count holds for the rows kept, so it is made on every row (prune = false), where the table's poles are all of them.
def unpruned(name, source):
    open(name, "w").write(open(source).read().replace("viscosity =", "prune = false\nviscosity ="))
unpruned("four_all.toml", "four.toml")
unpruned("one_all.toml", "one.toml")
g_all, a_all = roots_of(spectrum("four_all.toml")), roots_of(spectrum("one_all.toml"))
images_all = len(a_all) * 2
print("with every row: %d roots, (26)'s %d; with the rows no root needs left out: %d and %d" % (
    len(g_all), len(a_all), len(g_roots), len(a_roots)))
assert len(g_all) == images_all + 3 * len(poles), \
    "the four-tank chain has %d roots, (26)'s images and three uncoupled copies of the poles make %d" % (
        len(g_all), images_all + 3 * len(poles))
kept = len(a_roots) - (len(a_all) - len(poles) // 2)  # (26)'s roots: its bodies' and one per kept row
assert len(g_roots) == len(images) + 6 * kept, \
    "left out in both chains, the four-tank chain has %d roots where (26)'s images and its %d kept rows make %d" % (
        len(g_roots), kept, len(images) + 6 * kept)

# 2. confirm both ways, each on its own copy of the table (--refine-tables replaces the file).
for name in ("general.h5", "axial.h5"):
    subprocess.run(["cp", "sphere.h5", name], check=True)
four_tanks("four_c.toml", "general.h5")
one_tank("one_c.toml", "axial.h5")
p = subprocess.run([rom, "confirm", "four_c.toml", "--refine-tables", "--json", "--cavity-modes", modes],
                   capture_output=True, text=True)
if p.returncode != 0:
    sys.exit("chain-rom confirm (four tanks) exited %d: %s" % (p.returncode, p.stderr[-2000:]))
gc = json.loads(p.stdout)
p = subprocess.run([rom, "confirm", "one_c.toml", "--json", "--cavity-modes", modes], capture_output=True, text=True)
if p.returncode != 0:
    sys.exit("chain-rom confirm (one tank) exited %d: %s" % (p.returncode, p.stderr[-2000:]))
ac = json.loads(p.stdout)
print("confirm: four tanks %.1f s (%d rounds), (26) %.1f s" % (gc["seconds"], gc["rounds"], ac["seconds"]))
assert gc["unconfirmed"] == 0 and ac["unconfirmed"] == 0, "a root not confirmed"
assert gc.get("mesh_finer_levels") == 1, "the axisymmetric tables' mesh check should go a level finer"
pairs = []
for r in ac["roots"]:
    s0 = complex(*r["confirmed"])
    s1 = complex(*r["mesh_levels"][1])
    for turn in (lambda s: s + SPIN, lambda s: -(s.conjugate() + SPIN)):
        x = turn(s0)
        g = min(gc["roots"], key=lambda q: abs(complex(*q["confirmed"]) - x))
        if abs(complex(*g["confirmed"]) - x) < 1e-3 * SPIN:
            pairs.append((x, turn(s1), r, g))
assert pairs, "no confirmed root of the four-tank chain matches (26)'s"
for x, x1, r, g in pairs:
    d0 = abs(complex(*g["confirmed"]) - x) / SPIN
    d1 = abs(complex(*g["finer"]) - x1) / SPIN
    bar = abs(g["growth_error"] - r["growth_error"]) / max(r["growth_error"], 1e-300)
    print("  root %s: confirmed %.2e from (26)'s, on the finer tables %.2e from (26)'s level 1; growth %.6g +- %.2g "
          "(26: %.6g +- %.2g)" % (complex(*g["confirmed"]), d0, d1, g["growth"], g["growth_error"], r["growth"],
                                  r["growth_error"]))
    assert d0 < 1e-7, "the confirmed roots differ"
    assert d1 < 1e-6, "the mesh checks' finer roots differ"
    assert bar < 1e-2, "the error bars differ"
moved = max(q["moved"] for q in gc["roots"])
assert gc["rounds"] >= 1 and moved < 1e-8, "the confirmation should settle in rounds (last move %.2e)" % moved

# 3. A window without s = 0 is refused, saying what to make.
subprocess.run([modes, "response", "sphere", "--radius", "1", "--ekman", "1e-4", "--sigma", "0.2:2:31", "--order",
                "3", "--mesh-size", "0.4", "-o", "right.h5"], check=True, stdout=subprocess.DEVNULL)
four_tanks("right.toml", "right.h5")
p = subprocess.run([rom, "spectrum", "right.toml"], capture_output=True, text=True)
lines = p.stderr.strip().splitlines()
assert p.returncode != 0 and len(lines) == 1 and "FROM < 0 < TO" in lines[0], p.stderr
print("refused: " + lines[0][:160] + "...")
print("off_axis_krylov_check: all checks passed")
