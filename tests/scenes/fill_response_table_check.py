#!/usr/bin/env python3
"""Response tables of a partially filled tank (docs/viscous.md, "Response tables of a partially filled tank"), checked
end to end on Stewartson's top (data/scenes/stewartson_top.toml) with a coarse viscous liquid (Ek = 1e-2):

1. The Krylov (default), Galerkin and rational-fit (--fit: three fits of R(c) at c = -1, 0, 1, combined by their
   quadratic interpolation) tables' rows, two per pole with a + c t each, give R about a point at height -c below the
   liquid's centroid, R(c) = R_ff + 2c R_fg + c^2 R_gg, equal to forced solves (cavity-modes response --fill -o
   FILE.csv) at complex frequencies in and beyond the window, for c = 0, the top's own joint and c = -1.3; each table
   read without its t (as a filled tank's) misses R about the joint.
2. --exact-at: at a given complex frequency the Krylov table's R about the centroid is the forced solves' to rounding,
   R(c) at the other points to the table's error.
3. chain-rom with the Krylov and the fit table: its roots against chain-rom confirm's (22) with the liquid's own R,
   R_fg, R_gg; confirm --refine-tables then makes the Krylov table's roots the confirmed ones.

Usage: fill_response_table_check.py CAVITY_MODES CHAIN_ROM SCENE WORKDIR
"""
import json, os, re, shutil, subprocess, sys

import h5py
import numpy as np

modes_bin, rom_bin, scene, work = sys.argv[1:5]
os.makedirs(work, exist_ok=True)
failed = 0
text = open(scene).read()
spin = float(re.search(r"^spin = ([-0-9.e]+)", text, re.M).group(1))
L = float(re.search(r"^scale = ([-0-9.e]+)", text, re.M).group(1))
d = float(re.search(r"^center = ([-0-9.e]+)", text, re.M).group(1))
ekman = 1e-2
cavity = ["cylinder", "--radius", "1", "--height", "2", "--fill", "0.62", "--ekman", str(ekman), "--order", "3",
          "--mesh-size", "0.5"]
window = ["--sigma", "-3:2.5:23"]
probes = [0.3 + 0.05j, 0.97 + 0.06j, -0.8 + 0.1j, 1.7 - 0.02j, -2.02 + 0.3j, 0.55, 2.5]
exact = -1.3 + 0.04j
offsets = [0.0, d / L, -1.3]


def fail(message):
    global failed
    print("FAILED: " + message)
    failed += 1


def rows(path):
    """Each row's lambda_c, a_c and t_c."""
    with h5py.File(path) as h:
        m, fs = h["modes"], h["free_surface"]
        return (m["lambda"][:] + 1j * m["decay"][:], m["a"][:] + 1j * m["a_imag"][:], fs["t"][:] + 1j * fs["t_imag"][:])


def table_R(path, s, c):
    lam, a, t = rows(path)
    return np.array([np.sum(2 * (a + c * t) ** 2 / (x - lam)) for x in s])


def forced(s):
    """R, R_fg, R_gg by forced solves (the CSV)."""
    csv = os.path.join(work, "forced.csv")
    spec = ",".join(f"{x.real!r}{x.imag:+.17g}i" for x in s)
    subprocess.run([modes_bin, "response"] + cavity + ["--sigma", spec, "-o", csv], check=True, capture_output=True)
    v = np.array([[float(x) for x in l.split(",")] for l in open(csv) if l[0] not in "#s"])
    return v[:, 2] + 1j * v[:, 3], v[:, 4] + 1j * v[:, 5], v[:, 6] + 1j * v[:, 7]


ff, fg, gg = forced(probes)
# 1. Both table methods against the forced solves.
tables = {}
for method, extra, tolerance in (("krylov", ["--max-fit-error", "1e-7", "--exact-at",
                                             f"{exact.real!r}{exact.imag:+.17g}i"], 1e-6),
                                 ("galerkin", ["--galerkin", "--max-fit-error", "1e-6"], 1e-5),
                                 ("fit", ["--fit", "--max-fit-error", "1e-6"], 1e-5)):
    path = os.path.join(work, f"{method}.h5")
    r = subprocess.run([modes_bin, "response"] + cavity + window + extra + ["-o", path], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"the {method} response table with --fill: {r.stderr.strip()}"); continue
    tables[method] = path
    worst = 0
    for c in offsets:
        want = ff + 2 * c * fg + c * c * gg
        worst = max(worst, np.abs(table_R(path, probes, c) - want).max() / np.abs(want).max())
    lam, a, t = rows(path)
    joint = d / L
    want = ff + 2 * joint * fg + joint * joint * gg
    filled = np.abs(np.array([np.sum(2 * a * a / (x - lam)) for x in probes]) - want).max() / np.abs(want).max()
    if not filled > 1e-2:
        fail(f"the {method} table read without its t (as a filled tank's) should miss R about the joint")
    print(f"{method} table (fill 0.62, Ek = 1e-2): {len(lam)} rows ({len(set(lam))} poles); R(c) = R_ff + 2c R_fg + c^2 "
          f"R_gg from its rows against forced solves at {len(probes)} frequencies, c = {', '.join(f'{c:g}' for c in offsets)}: "
          f"{worst:.1e} of max|R(c)|; read without t (as a filled tank's) it misses R about the joint by {filled:.1e}")
    if not worst < tolerance:
        fail(f"the {method} table's rows are not the partially filled tank's response (allowed {tolerance:g})")
    if not np.all(lam.imag >= 0):
        fail(f"a pseudo-mode of the {method} table grows")

# 2. Exact where asked.
if "krylov" in tables:
    e_ff, e_fg, e_gg = forced([exact])
    gaps = [abs(table_R(tables["krylov"], [exact], c)[0] - (e_ff + 2 * c * e_fg + c * c * e_gg)[0]) /
            abs((e_ff + 2 * c * e_fg + c * c * e_gg)[0]) for c in offsets]
    print(f"--exact-at {exact}: the Krylov table's R(c) against forced solves, c = {offsets}: "
          + ", ".join(f"{g:.1e}" for g in gaps))
    # R about the centroid (c = 0) is exact to rounding: measured 1.4e-12, where the same table made without --exact-at
    # is 1.9e-9 off there (2026-11-29). About other points R(c) also needs the offset input's solution, which the basis
    # holds to 1e-9 on this mesh (3.7e-11 on the mesh before the contact-line fix): the table's own error elsewhere
    # (1e-7) bounds it.
    if not gaps[0] < 1e-10:
        fail("the Krylov table is not exact at its --exact-at frequency")
    if not max(gaps) < 1e-7:
        fail("the Krylov table's R(c) at its --exact-at frequency is off by more than its error elsewhere")

# 3. The chain: the table's roots against confirm's (Krylov and rational fit), then the Krylov table refined.
for method, allowed in (("krylov", 1e-6), ("fit", 1e-5)):
    if method not in tables:
        continue
    table = os.path.join(work, f"scene_{method}.h5")
    shutil.copy(tables[method], table)
    local = os.path.join(work, f"scene_{method}.toml")
    body = re.sub(r'^table = ".*"$', f'table = "{table}"\nviscosity = {ekman * spin * L * L!r}', text, flags=re.M)
    open(local, "w").write(body)
    conf = subprocess.run([rom_bin, "confirm", local, "--json"], capture_output=True, text=True)
    if conf.returncode not in (0, 1):
        fail(f"chain-rom confirm with the {method} table: {conf.stderr.strip()}"); continue
    roots = json.loads(conf.stdout)["roots"]
    moved = max(x["moved"] for x in roots)
    print(f"chain-rom with the {method} table: {len(roots)} body roots moved up to {moved:.1e} (of the spectral radius) "
          f"under confirm, which solves (22) with the liquid's own R, R_fg, R_gg; growth "
          f"{json.loads(conf.stdout)['growth']:.9g} 1/s confirmed")
    if not (moved < allowed and all(x["converged"] for x in roots)):
        fail(f"the chain's roots with the {method} table are not the confirmed ones to the table's error")
    if method == "krylov":
        refined = subprocess.run([rom_bin, "confirm", local, "--refine-tables"], capture_output=True, text=True)
        m = re.search(r"spectrum's roots are now the confirmed ones to ([0-9.e+-]+) relative", refined.stdout)
        print(f"confirm --refine-tables: {m.group(0) if m else refined.stderr.strip()}")
        if not (m and float(m.group(1)) < 1e-9):
            fail("confirm --refine-tables did not make the partially filled table's roots the confirmed ones")
sys.exit(1 if failed else 0)
