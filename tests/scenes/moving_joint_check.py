#!/usr/bin/python3
"""A partially filled tank on a body whose joint moves (docs/physics.md §2, "A tank whose joint moves"): Stewartson's top
(data/scenes/stewartson_top.toml) carried on a gimbal arm, the second body of a fixed chain, and the two floating free.

1. cavity-modes makes the top's table from the scene's "# recipe:" line;
2. the rigid limit: with the joint between arm and top stiff (κ² = 1e5 … 1e9 N m/rad) and both spinning alike, the
   chain is one rigid body whose tank sits s1 + d above the support; its roots (chain-rom on a one-body scene built
   here, the case docs/physics.md checks against the wall pressure) must be the chain's to within O(1/κ²): the
   joint's displacement s1 u1 enters the tank exactly as the centroid's own offset d u2 does;
3. Kononov (22) written out here for the two bodies from the table's datasets, the tank's coupling row
   β_l = (s1 t_l / L, a_l + c t_l) and its static form K over (u2, y = s1 u1): σ_min(Φ)/Σ‖terms‖ at every root chain-rom
   reports (off σ = 0) must be rounding — with the arm spinning like the top and with the arm not spinning (the tank's
   forcing uses its own body's spin); and the same Φ without the joint's terms (the tank as if its joint were fixed)
   is far from singular at some of them: the joint's motion matters;
4. chain-rom run on the stable chain keeps the energy of docs/rom.md "Energy" to rounding;
5. a viscous table of the same tank (coarse, Ek = 1e-2) on the arm: (22) with the complex rows at chain-rom's roots;
6. the free chain (docs/free-chain.md, "Partially filled tanks"; its base's translation eliminated through the chain's
   momentum, rom/model/base_translation.*) against the same chain carried by a massless, spinless arm 1 m long on a fixed
   support, whose tilt is the base's translation and which goes through section 3's joint levers instead: every root
   (ideal and viscous tank), and a run's tilts and fluid coordinates, to rounding;
7. chain-rom confirm with the viscous tank's own response (served by cavity-modes with --fill: R, R_fg, R_gg), on the
   arm and floating free: every confirmed root is a root of (22) written out here with R, R_fg, R_gg from
   cavity-modes response --fill -o CSV;
8. refused in one line, no file written: static_correction on such a tank, the nonlinear chain with it, a transverse
   force field with it.
usage: moving_joint_check.py CAVITY_MODES CHAIN_ROM SCENE WORKDIR
"""
import json, os, re, subprocess, sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from partial_fill_table import table_from_recipe, tank, value as scene_value  # noqa: E402

modes_bin, rom_bin, scene, work = sys.argv[1:5]
text, args, table = table_from_recipe(modes_bin, scene, work)

def value(key):
    return scene_value(text, key)

top = dict(mass=value("mass"), A=value("A"), C=value("C"), com=value("com"), spin=value("spin"))
rho, L, d, g = value("density"), value("scale"), value("center"), value("gravity")
arm = dict(mass=1.0, A=0.02, C=0.003, com=0.06, s=0.15)  # the gimbal arm: its next joint (the top's pivot) 15 cm up

def body_text(b, spin, next_joint=None, center=None):
    t = (f"[[body]]\nmass = {b['mass']!r}\nA = {b['A']!r}\nC = {b['C']!r}\ncom = {b['com']!r}\nspin = {spin!r}\n"
         + (f"next_joint = {next_joint!r}\n" if next_joint is not None else ""))
    if center is not None:
        t += f'[body.cavity]\ntable = "{table}"\ndensity = {rho!r}\nscale = {L!r}\ncenter = {center!r}\n'
    return t

def roots_of(scene_text, tag):
    path = os.path.join(work, tag + ".toml")
    open(path, "w").write(scene_text)
    out = subprocess.run([rom_bin, "spectrum", path, "--json", "--all"], capture_output=True, text=True)
    if out.returncode not in (0, 1):
        sys.exit(f"FAILED: chain-rom spectrum {tag} exited {out.returncode}: {out.stderr}")
    sp = json.loads(out.stdout)
    return np.array([complex(r[0], r[1]) for r in sp["roots"]]), sp

def chain_text(kappa2, arm_spin, kind="fixed", tank_table=None, viscosity=None):
    """The top on the arm; another table (a viscous one with its viscosity) in place of the top's when given."""
    text = (f"[system]\nkind = \"{kind}\"\ngravity = {g!r}\n" + body_text(arm, arm_spin, next_joint=arm["s"])
            + body_text(top, top["spin"], center=d) + f"[[joint]]\nstiffness = {kappa2!r}\nfriction = 0.0\n"
            + ("[support]\nfriction = 0.0\n" if kind == "fixed" else ""))
    if tank_table:
        text = text.replace(f'table = "{table}"', f'table = "{tank_table}"'
                            + (f"\nviscosity = {viscosity!r}" if viscosity else ""))
    return text

def on_massless_arm(free_text):
    """The free chain as a fixed one on a massless, spinless arm 1 m long (no gravity): the arm's tilt u0 moves the
    chain's base by X = 1 m · u0 and does nothing else, so this chain is the free one with its base's translation
    kept as a coordinate — through the joints' levers (section 3's code), not the free chain's momentum."""
    body0 = "[[body]]\nmass = 0.0\nA = 0.0\nC = 0.0\ncom = 0.0\nnext_joint = 1.0\nspin = 0.0\n"
    head, rest = free_text.split("[[body]]", 1)
    head = head.replace('kind = "free"', 'kind = "fixed"').replace(f"gravity = {g!r}", "gravity = 0.0")
    first_joint = "[[joint]]\nstiffness = 0.0\nfriction = 0.0\n"
    return head + body0 + "[[body]]" + rest.replace("[[joint]]", first_joint + "[[joint]]", 1) + \
        "[support]\nfriction = 0.0\n"

failed = 0
# 2. The rigid limit. The one body: both masses about the support, the top's inertia moved up by the parallel-axis
# theorem (its A is about its own pivot), its tank s1 + d above the support.
m1, m2, s1 = arm["mass"], top["mass"], arm["s"]
rigid = dict(mass=m1 + m2, com=(m1 * arm["com"] + m2 * (s1 + top["com"])) / (m1 + m2),
             A=arm["A"] + top["A"] - m2 * top["com"] ** 2 + m2 * (s1 + top["com"]) ** 2, C=arm["C"] + top["C"])
rigid_roots, _ = roots_of(f"[system]\nkind = \"fixed\"\ngravity = {g!r}\n" + body_text(rigid, top["spin"], center=s1 + d)
                          + "[support]\nfriction = 0.0\n", "rigid")
scale = np.max(np.abs(rigid_roots))
for kappa2 in (1e5, 1e7, 1e9):
    chain_roots, _ = roots_of(chain_text(kappa2, top["spin"]), f"stiff_{kappa2:.0e}")
    # each of the rigid body's roots against the nearest of the chain's (the chain has one fast joint pair more)
    gap = max(np.min(np.abs(chain_roots - r)) for r in rigid_roots) / scale
    print(f"joint stiffness {kappa2:.0e} N m/rad: the chain's roots are the rigid top's ({len(rigid_roots)}) to "
          f"{gap:.2e} of the spectral radius")
    last = gap
if not last < 1e-6:
    print("FAILED: the stiff chain is not the rigid top with its tank s1 + d above the support"); failed += 1

# 3. (22) for the two bodies, written out from the table.

L5, c, y = rho * L**5, d / L, s1 / L

def phi(sigma, kappa2, spins, tk, joint_terms=True):
    """Φ(σ) of docs/rom.md "Equations" with the tank's row β_l and form K (or, joint_terms False, without the joint's)."""
    m_f = rho * L**3 * tk["volume"]
    a1, a2 = m1 * arm["com"] + s1 * (m2 + m_f), m2 * top["com"] + m_f * d
    A2 = top["A"] + L5 * (tk["A_f"] + tk["K2"] + 2 * c * tk["K1"] + c * c * tk["K0"]) + m_f * d * d
    M = np.array([[arm["A"] + s1 * s1 * (m2 + m_f), a2 * s1], [a2 * s1, A2]], dtype=complex)
    if joint_terms:
        K0, K1 = tk["K0"], tk["K1"]
        M += L5 * np.array([[K0 * y * y, (K1 + c * K0) * y], [(K1 + c * K0) * y, 0]])
    G = np.diag([arm["C"] * spins[0], (top["C"] + L5 * tk["C_f"]) * spins[1]]) / sigma
    K = np.array([[-a1 * g + kappa2, -kappa2], [-kappa2, -a2 * g + kappa2]]) / sigma**2
    w = spins[1]
    beta = np.vstack([tk["t"] * y if joint_terms else 0 * tk["t"], tk["a"] + c * tk["t"]])  # 2 × modes
    weight = (sigma + w) * L5 * 2 / tk["N2"] / (sigma + w - tk["lam"] * w)
    fluid = (beta * weight) @ beta.T  # β βᵀ, no conjugate: a viscous mode's residue 2 a_c² is complex
    return M + G - K - fluid, sum(np.linalg.norm(x) for x in (M, G, K, fluid))

def sigma_min(sigma, *args):
    F, norm = phi(sigma, *args)
    return np.linalg.svd(F, compute_uv=False)[-1] / norm

ideal = tank(table)
for kappa2, arm_spin in ((1e4, top["spin"]), (50.0, 0.0)):
    roots, sp = roots_of(chain_text(kappa2, arm_spin), f"arm_spin_{arm_spin:g}")
    checked = [r for r in roots if abs(r) > 1e-9 * np.max(np.abs(roots))]
    spins = (arm_spin, top["spin"])
    res = max(sigma_min(r, kappa2, spins, ideal) for r in checked)
    fixed = max(sigma_min(r, kappa2, spins, ideal, False) for r in checked)
    print(f"arm spin {arm_spin:g} rad/s, joint {kappa2:g} N m/rad: stable = {sp['stable']}, growth {sp['growth']:.6g} "
          f"1/s; (22) written out here at {len(checked)} of chain-rom's {len(roots)} roots: sigma_min/terms <= "
          f"{res:.2e}; without the joint's terms up to {fixed:.2e}")
    tolerance = max(1e-9, 10 * sp["det_residual"])
    if not res < tolerance:
        print(f"FAILED: a root of chain-rom is not a root of (22) with the tank's row over both bodies"); failed += 1
    if not fixed > 1e-3:
        print("FAILED: the joint's terms should move the roots"); failed += 1

# 4. The motion: the stable chain (the arm spinning with the top) integrated from a tilted top keeps the energy of
# docs/rom.md "Energy", H = ½u̇ᴴM_eff u̇ + ½uᴴKu + ½Σ c_l |w_l|², w_l = z_l + β_lᵀu̇/β_l2 — an integral only if the
# first-order system couples each mode to both bodies as (22) does.
run_scene = os.path.join(work, "run.toml")
open(run_scene, "w").write(chain_text(1e4, top["spin"]) + "[initial]\ntilt = [[0.0, 0.0], [0.01, 0.0]]\n"
                           "rate = [[0.0, 0.0], [0.0, 0.0]]\n[run]\nt_end = 0.5\noutput_step = 0.0005\n")
history = os.path.join(work, "run.h5")
out = subprocess.run([rom_bin, "run", run_scene, "-o", history], capture_output=True, text=True)
if out.returncode != 0:
    sys.exit(f"FAILED: chain-rom run exited {out.returncode}: {out.stderr}")
with h5py.File(history) as h:
    drift = float(h.attrs["max_energy_drift"])
    top_tilt = np.max(np.abs(h["u_re"][:, 1] + 1j * h["u_im"][:, 1]))
print(f"run (exact, 0.5 s): largest relative energy drift {drift:.2e}, the top's largest tilt {top_tilt:.4f} rad")
if not drift < 1e-10:
    print("FAILED: the energy of the chain with the tank's row over both bodies is not an integral"); failed += 1

# 5. A viscous tank on the arm (Ek = 1e-2, a coarse mesh: (22) is checked against chain-rom, not the table against the
# liquid): complex rows β_l = (s1 t_c/L, a_c + c t_c) with a_c = a + i a_imag, t_c = t + i t_imag, λ_c = λ + i decay.
viscous = os.path.join(work, "viscous_fill.h5")
ek = 1e-2
subprocess.run([modes_bin, "cylinder", "--radius", "1", "--height", "2", "--fill", re.search(r"--fill ([0-9.]+)",
                args).group(1), "--ekman", str(ek), "--modes", "3", "--order", "3", "--mesh-size", "0.5",
                "--no-convergence-check", "-o", viscous], check=True, stdout=subprocess.DEVNULL)
vtext = chain_text(50.0, 0.0, tank_table=viscous, viscosity=ek * top["spin"] * L * L)
vroots, vsp = roots_of(vtext, "viscous")
vres = max(sigma_min(r, 50.0, (0.0, top["spin"]), tank(viscous)) for r in vroots if abs(r) > 1e-9 * np.max(np.abs(vroots)))
print(f"viscous tank (Ek = {ek:g}) on the arm: growth {vsp['growth']:.6g} 1/s; (22) with complex rows at chain-rom's "
      f"{len(vroots)} roots: sigma_min/terms <= {vres:.2e}")
if not vres < max(1e-9, 10 * vsp["det_residual"]):
    print("FAILED: a root of chain-rom with the viscous tank on the arm is not a root of (22)"); failed += 1

# 6. Free chains (docs/free-chain.md, "Partially filled tanks"): the arm and the top floating free, ideal and viscous
# tanks, against the same chain on a massless arm; and a run of both from the same tilt (zero momentum: no rates).
visc_nu = ek * top["spin"] * L * L
for label, tk, nu in (("ideal", table, None), (f"viscous (Ek = {ek:g})", viscous, visc_nu)):
    free = chain_text(50.0, 0.0, kind="free", tank_table=tk, viscosity=nu)
    roots, sp = roots_of(free, "free")
    arm_roots, _ = roots_of(on_massless_arm(free), "free_on_arm")
    far = np.max(np.abs(roots))
    gap = max(np.min(np.abs(arm_roots - r)) for r in roots) / far
    zeros = sorted(np.abs(arm_roots))[:2]  # the arm's tilt and rate: X and Ẋ, uniform motion
    print(f"free chain, {label} tank: growth {sp['growth']:.6g} 1/s, {len(roots)} roots; the same chain on a massless "
          f"arm: every root to {gap:.2e} of the spectral radius (its two more at |sigma| <= {max(zeros) / far:.1e})")
    if not (gap < 1e-10 and max(zeros) < 1e-8 * far):
        print("FAILED: the free chain's momentum reduction is not the chain with its base as a coordinate"); failed += 1

def history(scene_text, tag):
    path, out_h5 = os.path.join(work, tag + ".toml"), os.path.join(work, tag + ".h5")
    open(path, "w").write(scene_text)
    r = subprocess.run([rom_bin, "run", path, "-o", out_h5], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAILED: chain-rom run {tag} exited {r.returncode}: {r.stderr}")
    with h5py.File(out_h5) as h:
        return (h["u_re"][:] + 1j * h["u_im"][:], h["z_re"][:] + 1j * h["z_im"][:],
                float(h.attrs["max_energy_drift"]))

motion = "[initial]\ntilt = [[0.0, 0.0], [0.01, 0.0]]\nrate = [[0.0, 0.0], [0.0, 0.0]]\n[run]\nt_end = 0.5\noutput_step = 0.0005\n"
free = chain_text(50.0, 0.0, kind="free")  # stable (section 6): the energy is then a bounded integral
u_free, z_free, drift_free = history(free + motion, "free_run")
arm_motion = motion.replace("tilt = [[", "tilt = [[0.0, 0.0], [").replace("rate = [[", "rate = [[0.0, 0.0], [")
u_arm, z_arm, _ = history(on_massless_arm(free) + arm_motion, "free_run_on_arm")
du = np.max(np.abs(u_free - u_arm[:, 1:])) / np.max(np.abs(u_free))
dz = np.max(np.abs(z_free - z_arm)) / np.max(np.abs(z_free))
print(f"free chain run (0.5 s from the top tilted 0.01 rad, zero momentum): tilts = the massless arm chain's to {du:.2e}, "
      f"fluid coordinates to {dz:.2e}; energy drift {drift_free:.2e}")
if not (du < 1e-9 and dz < 1e-9 and drift_free < 1e-10):
    print("FAILED: the free chain's motion is not the chain's with its base as a coordinate"); failed += 1

# 7. confirm with the viscous tank's own response (cavity-modes serves R, R_fg, R_gg with --fill): its roots on the arm
# (fixed chain) and floating free are roots of (22) written out here with R, R_fg, R_gg from cavity-modes response
# --fill -o CSV at each root's body-frame frequency s = (σ + ω)/ω — the tank's form R e eᵀ + R_fg (e gᵀ + g eᵀ) +
# R_gg g gᵀ over its offset row g = (s1/L, c) (and 1/L on the base's translation X).
viscous_args = ["cylinder", "--radius", "1", "--height", "2", "--fill", re.search(r"--fill ([0-9.]+)", args).group(1),
                "--ekman", str(ek), "--order", "3", "--mesh-size", "0.5"]

def responses(sigmas, spin):
    """R, R_fg, R_gg (each an array over sigmas) at s = (σ + ω)/ω, by cavity-modes response --fill."""
    s_values = [(x + spin) / spin for x in sigmas]
    csv = os.path.join(work, "R.csv")
    spec = ",".join(f"{z.real!r}{z.imag:+.17g}i" for z in s_values)
    subprocess.run([modes_bin, "response"] + viscous_args + ["--sigma", spec, "-o", csv], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    rows = np.array([[float(v) for v in l.split(",")] for l in open(csv) if l[0] not in "#s"])
    return np.array(s_values), rows[:, 2] + 1j * rows[:, 3], rows[:, 4] + 1j * rows[:, 5], rows[:, 6] + 1j * rows[:, 7]

def phi_with_response(sigma, kappa2, tk, s, R, R_fg, R_gg, free):
    """(22) on the arm (2 × 2) or free (3 × 3 with X, docs/free-chain.md) with the tank's own response."""
    m_f = rho * L**3 * tk["volume"]
    a1, a2 = m1 * arm["com"] + s1 * (m2 + m_f), m2 * top["com"] + m_f * d
    A2 = top["A"] + L5 * (tk["A_f"] + tk["K2"] + 2 * c * tk["K1"] + c * c * tk["K0"]) + m_f * d * d
    K0, K1 = tk["K0"], tk["K1"]
    M = np.array([[arm["A"] + s1 * s1 * (m2 + m_f) + L5 * K0 * y * y, a2 * s1 + L5 * (K1 + c * K0) * y],
                  [a2 * s1 + L5 * (K1 + c * K0) * y, A2]], dtype=complex)
    g_row, e_row = np.array([y, c]), np.array([0.0, 1.0])
    G = np.diag([0.0, (top["C"] + L5 * tk["C_f"]) * top["spin"]]) / sigma
    K = np.array([[kappa2, -kappa2], [-kappa2, kappa2]]) / sigma**2 if free else \
        np.array([[-a1 * g + kappa2, -kappa2], [-kappa2, -a2 * g + kappa2]]) / sigma**2
    if free:  # X: the chain's first moments a, its mass, K over X; no G, K on X
        M = np.pad(M, ((0, 1), (0, 1)))
        M[2, :2] = M[:2, 2] = [a1 + L5 * K0 * y / L, a2 + L5 * (K1 + c * K0) / L]
        M[2, 2] = m1 + m2 + m_f + L5 * K0 / L**2
        G, K = np.pad(G, ((0, 1), (0, 1))), np.pad(K, ((0, 1), (0, 1)))
        g_row, e_row = np.append(g_row, 1 / L), np.append(e_row, 0.0)
    tank = L5 * s * (R * np.outer(e_row, e_row) + R_fg * (np.outer(e_row, g_row) + np.outer(g_row, e_row))
                     + R_gg * np.outer(g_row, g_row))
    F = M + G - K - tank
    return np.linalg.svd(F, compute_uv=False)[-1] / sum(np.linalg.norm(x) for x in (M, G, K, tank))

vtank = tank(viscous)
for kind in ("fixed", "free"):
    path = os.path.join(work, f"confirm_{kind}.toml")
    open(path, "w").write(chain_text(50.0, 0.0, kind=kind, tank_table=viscous, viscosity=visc_nu))
    r = subprocess.run([rom_bin, "confirm", path, "--json"], capture_output=True, text=True)
    if r.returncode != 0:
        print(f"FAILED: chain-rom confirm ({kind}) exited {r.returncode}: {r.stderr.strip()}"); failed += 1
        continue
    confirmed = [complex(*x["confirmed"]) for x in json.loads(r.stdout)["roots"]]
    moved = max(x["moved"] for x in json.loads(r.stdout)["roots"])
    s_values, R, R_fg, R_gg = responses(confirmed, top["spin"])
    worst = max(phi_with_response(z, 50.0, vtank, s_values[i], R[i], R_fg[i], R_gg[i], kind == "free")
                for i, z in enumerate(confirmed))
    print(f"confirm ({kind} chain, viscous tank): {len(confirmed)} roots moved up to {moved:.1e} from the table's; (22) "
          f"with the CSV's R, R_fg, R_gg at them: sigma_min/terms <= {worst:.2e}")
    if not worst < 1e-9:
        print("FAILED: a confirmed root is not a root of (22) with the tank's own response"); failed += 1

# 8. Refused in one line: the static correction on a body whose joint moves, the nonlinear chain with such a tank.
def refused(scene_text, command, phrase):
    global failed
    path = os.path.join(work, "refused.toml")
    open(path, "w").write(scene_text)
    out_file = os.path.join(work, "x.csv" if command[0] == "sweep" else "x.h5")
    if os.path.exists(out_file):
        os.remove(out_file)
    r = subprocess.run([rom_bin] + command + [path] + (["-o", out_file] if command[0] in ("sweep", "run") else []),
                       capture_output=True, text=True)
    lines = r.stderr.strip().splitlines()
    ok = r.returncode == 1 and len(lines) == 1 and phrase in lines[0] and not os.path.exists(out_file)
    print(f"{'refused' if ok else 'FAILED to refuse'} ({r.returncode}): {r.stderr.strip()}")
    failed += 0 if ok else 1

refused(chain_text(50.0, 0.0).replace(f'center = {d!r}', f'center = {d!r}\nstatic_correction = true'), ["spectrum"],
        "not modelled for a partially filled tank on a body whose joint moves")
refused(chain_text(50.0, 0.0) + motion.replace("[run]\n", "[run]\nmodel = \"nonlinear\"\n"), ["run"],
        "on the first body of a fixed chain only")
refused(chain_text(50.0, 0.0).replace("[[body]]", "[field]\nspace = [0.5, 0.0, 0.0]\n[[body]]", 1), ["spectrum"],
        "a transverse field moves a partially filled tank's free surface")
sys.exit(1 if failed else 0)
