#!/usr/bin/env python3
"""The spectral sphere table in the chain, and the finite elements' sphere table checked against it.

  spectral_sphere_check.py CAVITY_MODES CHAIN_ROM DIR

The spacecraft of data/scenes/spacecraft_nutation.toml (free, 800 kg, A 400, C 520 kg m^2, 60 rpm) with its tank
completely full and a liquid 1 100 times as viscous as hydrazine (Ek = 1e-3, so that both tables take seconds):
1. `cavity-modes shell --ekman 1e-3 --sigma -1.5:2:41 -o spectral.h5` (docs/spherical.md, "Response tables") and the
   finite elements' default Krylov table of the same sphere (`cavity-modes response sphere ...`) on the same window;
2. `chain-rom spectrum --json` with each: the body roots (nutation) of the two agree to 3e-6 relative in frequency and
   decay rate (the spectral table is the reference; its own truncation change is printed);
3. `chain-rom confirm` on the spectral table (the served spectral solves, `shell --serve`; its study raises the
   truncation 1.5 times): the confirmed nutation equals the table's root to 1e-6, and the study says converged;
4. a table made at `--mesh-level 1` is served at its own truncation (level 1, its unknowns), its study at level 2."""
import json, os, subprocess, sys

modes, rom, out = sys.argv[1:4]
os.makedirs(out, exist_ok=True)
os.chdir(out)
ek, spin, L = 1e-3, 6.2832, 0.4
window = ["--sigma", "-1.5:2:41"]
run = lambda args: subprocess.run(args, capture_output=True, text=True)

p = run([modes, "shell", "--ekman", repr(ek)] + window + ["--max-fit-error", "1e-7", "-o", "spectral.h5"])
print(p.stdout + p.stderr[-600:])
if p.returncode != 0:
    sys.exit("cavity-modes shell exited %d" % p.returncode)
p = run([modes, "response", "sphere", "--radius", "1", "--ekman", repr(ek)] + window +
        ["--max-fit-error", "1e-7", "-o", "fe.h5"])
if p.returncode != 0:
    sys.exit("cavity-modes response exited %d: %s" % (p.returncode, p.stderr[-400:]))


def scene(table):
    nu = ek * spin * L * L
    name = "scene_%s.toml" % table.split(".")[0]
    open(name, "w").write(
        '[system]\nkind = "free"\ngravity = 0.0\n[[body]]\nmass = 800.0\nA = 400.0\nC = 520.0\ncom = 0.0\n'
        'spin = %r\n[body.cavity]\ntable = "%s"\ndensity = 1004.0\nscale = %r\ncenter = 0.3\nviscosity = %r\n'
        % (spin, table, L, nu))
    return name


def nutation(table):
    """The slowest-decaying root away from sigma = 0: the nutation (the fluid's roots decay 100 times faster)."""
    p = run([rom, "spectrum", scene(table), "--json"])
    if p.returncode != 0:
        sys.exit("chain-rom spectrum exited %d: %s" % (p.returncode, p.stderr[-400:]))
    return min((complex(*r) for r in json.loads(p.stdout)["roots"] if abs(complex(*r)) > 1e-6), key=lambda z: z.imag)


spectral, fe = nutation("spectral.h5"), nutation("fe.h5")
gap = max(abs(fe.real - spectral.real) / abs(spectral.real), abs(fe.imag - spectral.imag) / abs(spectral.imag))
print("nutation: spectral table %.10g%+.6ei, finite elements' table %.10g%+.6ei: %.1e apart" % (
    spectral.real, spectral.imag, fe.real, fe.imag, gap))
assert gap <= 3e-6, "the finite elements' sphere table is %.1e off the spectral one" % gap

p = run([rom, "confirm", scene("spectral.h5"), "--json", "--cavity-modes", modes])
print(p.stderr[-800:])
if p.returncode != 0:
    sys.exit("chain-rom confirm exited %d" % p.returncode)
res = json.loads(p.stdout)
root = min(res["roots"], key=lambda r: abs(complex(*r["confirmed"]) - spectral))
c = complex(*root["confirmed"])
gap = max(abs(c.real - spectral.real) / abs(spectral.real), abs(c.imag - spectral.imag) / abs(spectral.imag))
print("confirm: nutation %.10g%+.6ei (the table's root %.1e apart), decay %.6g +- %.2g, mesh_converged %s" % (
    c.real, c.imag, gap, -root["growth"], root["growth_error"], root["mesh_converged"]))
assert gap <= 1e-6, "the confirmed root is %.1e off the spectral table's" % gap
assert root["mesh_converged"], "the spectral truncation study says not converged"

p = run([modes, "shell", "--ekman", repr(ek), "--mesh-level", "1"] + window + ["--max-fit-error", "1e-7", "-o",
        "level1.h5"])
if p.returncode != 0:
    sys.exit("cavity-modes shell --mesh-level 1 exited %d: %s" % (p.returncode, p.stderr[-400:]))
p = run([rom, "confirm", scene("level1.h5"), "--cavity-modes", modes])
log = p.stdout + p.stderr
served = [l.strip() for l in log.splitlines() if l.strip().startswith("body 1:")]
print("\n".join(served))
assert p.returncode == 0, log[-400:]
assert "NOT the table's mesh" not in log, log
assert served and served[0].endswith("--mesh-level 1 --serve") and served[-1].endswith("--mesh-level 2 --serve"), served
print("spectral_sphere_check: ok")
