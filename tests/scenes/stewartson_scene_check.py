#!/usr/bin/python3
"""A top with a partially filled tank end to end (Stewartson's top, data/scenes/stewartson_top.toml, and the spacecraft
on its spin-test stand and in free flight, data/scenes/spacecraft_spin_table.toml and spacecraft_free.toml), and its roots against Kononov (22) written out here.

1. cavity-modes makes the scene's partially filled tank's table from its "# recipe:" line;
2. chain-rom spectrum --json on a copy of the scene pointed at it: the verdict its "# expect:" line states (Stewartson's
   top: unstable, the nutation meeting the liquid's heaviest mode, Stewartson 1959);
3. at every root chain-rom reports, the characteristic function of docs/physics.md §3,
     F(σ) = A′ + C ω/σ + a g/σ² − (σ + ω) Σ_l E_l(O)/(σ + ω − λ_l ω),
   with the tank taken about the joint as docs/physics.md §2 ("Partially filled tanks") says — E_l(O) = 2(a_l + c t_l)²
   and A′ = A + ρL⁵(A_f + K(c)) + m_f d², c = d/L — is computed from the table's own datasets (h5py), independently
   of chain-rom's model: |F| at the roots must be rounding against its terms (a free body, kind = "free": without
   gravity, and reduced on the body's translation X, F − F_uX²/F_XX with the tank's row (a + c t, t/L) and K over
   (u, X): docs/free-chain.md, "Partially filled tanks");
4. the same table read as if filled (t and K dropped) gives other roots: the free surface's terms matter; with
   --refusals also a viscous table of the same tank (Ek = 1e-3): chain-rom's roots against (22) with complex
   lambda_c = lambda + i decay and a_c + c t_c;
5. the nonlinear chain with this tank at a stable fill (0.9) against the linear one: the difference falls as the
   amplitude squared; what is not modelled yet is refused in one line, no file written: a section's fill that cuts it into pieces or meets it twice, a .msh or drawn
   free surface with --fill, --fill with --target, with --fields, separable around a rod and outside (0, 1]
   (cavity-modes, exit 2), cluster options with --fill,
   and a section with a 'free' group, with or without --fill (exit 1) — with --refusals only.
usage: stewartson_scene_check.py CAVITY_MODES CHAIN_ROM SCENE WORKDIR [--refusals]
"""
import json, os, re, subprocess, sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from partial_fill_table import table_from_recipe, tank, value as scene_value  # noqa: E402

modes_bin, rom_bin, scene, work = sys.argv[1:5]
text, args, table = table_from_recipe(modes_bin, scene, work)
local = os.path.join(work, "scene.toml")
open(local, "w").write(re.sub(r'^table = ".*"$', f'table = "{table}"', text, flags=re.M))
out = subprocess.run([rom_bin, "spectrum", local, "--json", "--all"], capture_output=True, text=True)
if out.returncode not in (0, 1):
    sys.exit(f"FAILED: chain-rom spectrum exited {out.returncode}: {out.stderr}")
spectrum = json.loads(out.stdout)
roots = [complex(r[0], r[1]) for r in spectrum["roots"]]
print(f"chain-rom: stable = {spectrum['stable']}, margin {spectrum['margin']:.6g} rad/s, {len(roots)} roots")
failed = 0
expect = re.search(r"^# expect: (stable|unstable)$", text, re.M).group(1)
if spectrum["stable"] != (expect == "stable"):
    print(f"FAILED: the scene should be {expect}"); failed += 1

def value(key):
    return scene_value(text, key)

mass, A, C, com, spin = value("mass"), value("A"), value("C"), value("com"), value("spin")
rho, L, d, g = value("density"), value("scale"), value("center"), value("gravity")

ideal = tank(table)
L5 = rho * L**5

free_chain = re.search(r'^kind = "free"', text, re.M) is not None

def F(sigma, tk, free_surface=True, derivative=False):
    """(22) at sigma, the size of its largest term, and with `derivative` its derivative in sigma."""
    c = d / L
    t = tk["t"] if free_surface else 0 * tk["t"]
    a_O = tk["a"] + c * t
    pole = sigma + spin - tk["lam"] * spin
    weight = (sigma + spin) * L5 * 2 / tk["N2"] / pole
    dweight = -tk["lam"] * spin * L5 * 2 / tk["N2"] / pole**2  # d weight / d sigma
    K = L5 * (tk["K2"] + 2 * c * tk["K1"] + c * c * tk["K0"]) if free_surface else 0.0
    m_f = rho * L**3 * tk["volume"]
    A1 = A + L5 * tk["A_f"] + m_f * d * d + K
    a1 = mass * com + m_f * d
    terms = [A1, (C + L5 * tk["C_f"]) * spin / sigma] + ([] if free_chain else [a1 * g / sigma**2])
    dterms = -(C + L5 * tk["C_f"]) * spin / sigma**2 + (0 if free_chain else -2 * a1 * g / sigma**3)
    fluid = weight * a_O**2
    F_uu, dF_uu = sum(terms) - fluid.sum(), dterms - (dweight * a_O**2).sum()
    if not free_chain:
        value, scale, slope = F_uu, max(abs(x) for x in terms + list(abs(fluid))), dF_uu
        return (value, scale, slope) if derivative else (value, scale)
    # A free body: its translation X kept and eliminated (docs/free-chain.md, "Partially filled tanks"): the Schur
    # complement F_uu - F_uX²/F_XX, the tank's row (a + c t, t/L) and K over (u, X).
    k_uX = L5 / L * (tk["K1"] + c * tk["K0"]) if free_surface else 0.0
    k_XX = L5 / L**2 * tk["K0"] if free_surface else 0.0
    F_uX = a1 + k_uX - (weight * a_O * t / L).sum()
    F_XX = mass + m_f + k_XX - (weight * (t / L) ** 2).sum()
    dF_uX, dF_XX = -(dweight * a_O * t / L).sum(), -(dweight * (t / L) ** 2).sum()
    value = F_uu - F_uX**2 / F_XX
    scale = max(abs(x) for x in terms + [abs(F_uX) ** 2 / abs(F_XX)] + list(abs(fluid)))
    slope = dF_uu - (2 * F_uX * dF_uX * F_XX - F_uX**2 * dF_XX) / F_XX**2
    return (value, scale, slope) if derivative else (value, scale)

def worst_residual(roots, tk):
    """Per root off sigma = 0 (see below) the smaller of |F|/max|term| and the backward error |F/F'|/|sigma|, the
    Newton step that would move it, relative: a root within E_l of a very light mode's pole (E ~ 1e-13, a mode that
    barely couples) sits closer to it than a double resolves, so |F| is O(1) there however exact the root, while the
    step that would move it stays at rounding. The worst over the roots, and how many."""
    checked = [r for r in roots if abs(r) > 1e-9 * spin]
    def error(r):
        value, scale, slope = F(r, tk, derivative=True)
        return min(abs(value) / scale, abs(value / slope) / abs(r))
    return max(error(r) for r in checked), len(checked)

# sigma = 0 is no root of F (its terms C w/sigma, a g/sigma^2 diverge there): a mode at lambda = 1 (the partially
# filled sphere's rigid tilt, steady in space) puts one there, which chain-rom too leaves unchecked.
worst, checked = worst_residual(roots, ideal)
print(f"(22) written out here, at {checked} of chain-rom's {len(roots)} roots (not at sigma = 0): worst "
      f"|F|/max|term| or Newton step |F/F'|/|sigma| = {worst:.2e}")
# A root within E_l of a light mode's pole is as ill-conditioned as chain-rom's own det residual says (the projectile's
# payload: 1.1e-9 at its light, fast-decaying mode): the check allows ten times that, and 1e-9 at least.
tolerance = max(1e-9, 10 * spectrum["det_residual"])
if not worst < tolerance:
    print(f"FAILED: a root of chain-rom is not a root of (22) with the tank about its joint (tolerance {tolerance:.1e})")
    failed += 1
body = [r for r in roots if r.imag < 0] or roots
filled = max(abs(F(r, ideal, False)[0]) / F(r, ideal, False)[1] for r in body)
print(f"the same table read as if filled (no t, no K): |F|/max|term| at the roots {filled:.2e} (the free "
      f"surface's terms move the roots)")
if not filled > 1e-3:
    print("FAILED: the free surface's terms should matter at this top"); failed += 1

if "--refusals" not in sys.argv[5:]:
    sys.exit(1 if failed else 0)

def read_response(path):
    rows = [l for l in open(path) if l[0] not in "#s"]
    return [[float(v) for v in l.split(",")] for l in rows]

def refused(command, code, phrase, output=None):
    global failed
    if output and os.path.exists(output):
        os.remove(output)  # a stale file of an earlier run must not count against this one
    r = subprocess.run(command, capture_output=True, text=True)
    lines = r.stderr.strip().splitlines()
    ok = (r.returncode == code if code else r.returncode != 0) and len(lines) == 1 and phrase in lines[0]
    ok = ok and not (output and os.path.exists(output))
    print(f"{'refused' if ok else 'FAILED to refuse'} ({r.returncode}): {' '.join(command[1:4])} ... : {r.stderr.strip()}")
    failed += 0 if ok else 1

# The nonlinear chain with the tank (its modes about the joint, K in A and B): at a fill outside the unstable band
# (0.9) the top's tilt from the linear and the nonlinear model must differ by a relative amount that falls as the
# amplitude squared, from a small one (docs/rom.md, "Partially filled tanks").
stable_table = os.path.join(work, "cylinder_fill0.9.h5")
subprocess.run([modes_bin, "cylinder", "--radius", "1", "--height", "2", "--fill", "0.9", "-o", stable_table], check=True,
               stdout=subprocess.DEVNULL)
def tilt_history(amplitude, model):
    scene_text = re.sub(r'^table = ".*"$', f'table = "{stable_table}"', open(local).read(), flags=re.M)
    scene_text = scene_text.replace("tilt = [[0.01, 0.0]]", f"tilt = [[{amplitude!r}, 0.0]]")
    scene_text = scene_text.replace('method = "exact"', 'method = "exact"' if model == "linear" else 'model = "nonlinear"')
    path, out_h5 = os.path.join(work, f"{model}_{amplitude}.toml"), os.path.join(work, f"{model}_{amplitude}.h5")
    open(path, "w").write(scene_text)
    r = subprocess.run([rom_bin, "run", path, "-o", out_h5], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAILED: chain-rom run ({model}) exited {r.returncode}: {r.stderr}")
    with h5py.File(out_h5) as h:
        return h["t"][:], h["u_re"][:, 0] + 1j * h["u_im"][:, 0]
gaps = []
for amplitude in (0.004, 0.008):
    t_lin, u_lin = tilt_history(amplitude, "linear")
    t_nl, u_nl = tilt_history(amplitude, "nonlinear")
    u_at = np.interp(t_lin, t_nl, u_nl.real) + 1j * np.interp(t_lin, t_nl, u_nl.imag)
    gaps.append(np.max(np.abs(u_at - u_lin)) / np.max(np.abs(u_lin)))
ratio = gaps[1] / gaps[0]
print(f"nonlinear chain against the linear one, fill 0.9 (stable), 0.5 s: relative difference {gaps[0]:.2e} at 0.004 rad, "
      f"{gaps[1]:.2e} at 0.008 rad (ratio {ratio:.2f}, amplitude squared: 4)")
if not (gaps[1] < 1e-3 and 3 < ratio < 5):
    print("FAILED: the nonlinear chain with the partially filled tank is not the linear one at small amplitude"); failed += 1
x = os.path.join(work, "refused.h5")
# Sections cut at their free surface: one liquid region and one free-surface segment, from a .geo file. The pieces
# section is 0.2 < r < 1, |z| < 1 with a notch 0.5 < r < 1, |z| < 0.1 (two arms beyond r = 0.84 at fill 0.3); the
# segments section has the notch on its inner side, 0.2 < r < 0.6 (r = 0.30 at fill 0.95 meets it above and below).
def section_file(name, points):
    n = len(points)
    text = "".join(f"Point({i + 1}) = {{{r}, {z}, 0}};\n" for i, (r, z) in enumerate(points))
    text += "".join(f"Line({i + 1}) = {{{i + 1}, {(i + 1) % n + 1}}};\n" for i in range(n))
    loop = ", ".join(str(i + 1) for i in range(n))
    text += (f'Curve Loop(1) = {{{loop}}};\nPlane Surface(1) = {{1}};\nPhysical Surface("fluid") = {{1}};\n'
             f'Physical Curve("wall") = {{{loop}}};\n')
    path = os.path.join(work, name)
    open(path, "w").write(text)
    return path
pieces = section_file("pieces.geo", [(0.2, -1), (1, -1), (1, -0.1), (0.5, -0.1), (0.5, 0.1), (1, 0.1), (1, 1), (0.2, 1)])
segments = section_file("segments.geo",
                        [(0.2, -1), (1, -1), (1, 1), (0.2, 1), (0.2, 0.1), (0.6, 0.1), (0.6, -0.1), (0.2, -0.1)])
refused([modes_bin, "section", pieces, "--fill", "0.3", "-o", x], 2, "cuts the liquid into 2 pieces", x)
refused([modes_bin, "section", segments, "--fill", "0.95", "-o", x], 2, "in 2 separate segments", x)
mesh_file = os.path.join(work, "section.msh")
open(mesh_file, "w").write("")
refused([modes_bin, "section", mesh_file, "--fill", "0.5", "-o", x], 2, "only a .geo file holds", x)
drawn = os.path.join(work, "drawn_free.geo")
open(drawn, "w").write(open(pieces).read().replace('Physical Curve("wall") = {1, 2, 3, 4, 5, 6, 7, 8};',
                                                    'Physical Curve("wall") = {1, 2, 3, 4, 5, 6, 7};\n'
                                                    'Physical Curve("free") = {8};'))
for fill in ([], ["--fill", "0.5"]):
    refused([modes_bin, "section", drawn] + fill + ["-o", x], 0, "a 1D physical group 'free'", x)
refused([modes_bin, "cylinder", "--radius", "1", "--height", "2", "--inner-radius", "0.3", "--fill", "0.5", "--method",
         "separable", "-o", x], 2, "a plain cylinder only", x)
refused([modes_bin, "sphere", "--radius", "1", "--fill", "0.5", "--ekman", "1e-3", "--fields", "-o", x], 2,
        "not with --fields yet", x)
refused([modes_bin, "cylinder", "--radius", "1", "--height", "2", "--fill", "0.5", "--method", "separable", "--fields",
         "-o", x], 0, "needs --method mesh", x)
refused([modes_bin, "sphere", "--radius", "1", "--fill", "0.5", "--clusters", "slices", "-o", x], 0,
        "does not apply with --fill", x)
refused([modes_bin, "cylinder", "--radius", "1", "--height", "2", "--fill", "0.5", "--ekman", "1e-3", "--target", "0.5",
         "-o", x], 2, "not with --target", x)
# The ideal partially filled tank's response: the mesh method's sums over every pair against the separable
# cylinder's.
ideal_csv = [os.path.join(work, f"ideal_response_{m}.csv") for m in ("mesh", "separable")]
for m, path in zip(("mesh", "separable"), ideal_csv):
    subprocess.run([modes_bin, "response", "cylinder", "--radius", "1", "--height", "2", "--fill", "0.9", "--method", m,
                    "--sigma", "0.5+0.3i,1.2+0.1i,-0.7+0.05i", "-o", path], capture_output=True)
if all(os.path.exists(p) for p in ideal_csv):
    a, b = (read_response(p) for p in ideal_csv)
    scale = max(abs(complex(r[2], r[3])) for r in b)
    gap = max(abs(complex(x[k], x[k + 1]) - complex(y[k], y[k + 1])) for x, y in zip(a, b) for k in (2, 4, 6)) / scale
    print(f"ideal response --fill 0.9: mesh method against the separable cylinder, R, R_fg, R_gg to {gap:.1e} of max|R|")
    if not gap < 1e-6:
        print("FAILED: the two ideal partially filled responses differ"); failed += 1
else:
    print("FAILED: cavity-modes response --fill (ideal) wrote no CSV"); failed += 1
# Served (chain-rom confirm's route): one line of R, R_fg, R_gg per frequency, the CSV's numbers to rounding.
coarse = ["cylinder", "--radius", "1", "--height", "2", "--fill", "0.9", "--ekman", "1e-2", "--order", "3",
          "--mesh-size", "0.5"]
served = subprocess.run([modes_bin, "response"] + coarse + ["--serve"], input="0.7+0.05i\n", capture_output=True,
                        text=True).stdout.splitlines()
served_csv = os.path.join(work, "served.csv")
subprocess.run([modes_bin, "response"] + coarse + ["--sigma", "0.7+0.05i", "-o", served_csv], capture_output=True)
if len(served) == 2 and served[0].startswith("ready: ") and os.path.exists(served_csv):
    got, want = [float(v) for v in served[1].split()], read_response(served_csv)[0][2:8]
    gap = max(abs(p - q) for p, q in zip(got, want)) / max(abs(q) for q in want)
    print(f"response --fill --serve: R, R_fg, R_gg = the CSV's to {gap:.1e}")
    if not (len(got) == 6 and gap < 1e-12):
        print("FAILED: the served partially filled response is not the CSV's"); failed += 1
else:
    print(f"FAILED: response --fill --serve answered {served}"); failed += 1
for bad in ("0", "1.5", "-0.2", "abc"):
    refused([modes_bin, "cylinder", "--radius", "1", "--height", "2", "--fill", bad, "-o", x], 2,
            "volume fraction must be in (0, 1]", x)
# A viscous partially filled table (damped modes with the free surface, Ek = 1e-3): the chain's roots with it are
# roots of (22) with complex lambda_c and a_c + c t_c, written out here. Both read the same table, so any mesh will do:
# P3, h 0.25 (2.2 s against 21 s at the default P6, 2026-12-03).
viscous = os.path.join(work, "viscous_fill.h5")
r = subprocess.run([modes_bin, "cylinder", "--radius", "1", "--height", "2", "--fill", "0.62", "--ekman", "1e-3",
                    "--modes", "4", "--order", "3", "--mesh-size", "0.25", "--no-convergence-check", "-o", viscous],
                   capture_output=True, text=True)
if r.returncode != 0:
    print(f"FAILED: the viscous partially filled table: {r.stderr.strip()}"); failed += 1
else:
    vscene = os.path.join(work, "viscous.toml")
    open(vscene, "w").write(re.sub(r'^table = ".*"$', f'table = "{viscous}"\nviscosity = {1e-3 * spin * L * L}',
                                   open(local).read(), flags=re.M))
    out = subprocess.run([rom_bin, "spectrum", vscene, "--json", "--all"], capture_output=True, text=True)
    vroots = [complex(x[0], x[1]) for x in json.loads(out.stdout)["roots"]] if out.returncode in (0, 1) else []
    if not vroots:
        print(f"FAILED: chain-rom spectrum with the viscous table: {out.stderr.strip()}"); failed += 1
    else:
        vworst, vchecked = worst_residual(vroots, tank(viscous))
        grows = max(-x.imag for x in vroots)
        print(f"viscous tank (Ek = 1e-3): (22) with complex lambda_c and a_c + c t_c at {vchecked} roots: worst "
              f"|F|/max|term| = {vworst:.2e}; largest growth {grows:.4g} 1/s")
        if not vworst < 1e-9:
            print("FAILED: a root of chain-rom with the viscous tank is not a root of (22)"); failed += 1
annulus = open(os.path.join(os.path.dirname(scene), "..", "sections", "annulus.geo")).read()
free_geo = os.path.join(work, "annulus_free.geo")
open(free_geo, "w").write(annulus.replace('Physical Curve("wall") = {1, 2, 3, 4};',
                                          'Physical Curve("wall") = {1, 2, 3};\nPhysical Curve("free") = {4};'))
refused([modes_bin, "section", free_geo, "--modes", "3", "-o", x], 1, "'free' (a free surface) is not read", x)
sys.exit(1 if failed else 0)
