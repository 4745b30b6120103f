#!/usr/bin/env python3
"""data/scenes/projectile_annular.toml end to end at low cost: a ring-shaped tank (no axis) in the chain.

  ring_scene_check.py CAVITY_MODES CHAIN_ROM SCENE DIR

1. Viscous: the scene's recipe (a Krylov response table of the annular cylinder) on a P3 mesh; `chain-rom confirm
   --refine-tables`; every confirmed root checked independently with R(s) by a separate `cavity-modes response
   --sigma s -o R.csv` in the one-body (22), Phi(sigma) = A' + C w/sigma + a g/sigma^2 - rho L^5 s R(s) (below 1e-9
   of its terms); the refined table's spectrum equals the confirmed roots to 1e-9; the nutation grows.
2. Ideal twin: the same annulus by the separable method (every eigenpair), 40 modes kept with the static correction;
   the chain is then stable (all roots real: the liquid's viscosity is what makes the nutation grow), and the viscous
   nutation's frequency is the ideal one's to 5e-3 (Ek = 1.3e-6)."""
import json, os, re, shlex, subprocess, sys

modes, rom, scene, out = sys.argv[1:5]
os.makedirs(out, exist_ok=True)
os.chdir(out)
text = open(scene).read()
name, args = re.search(r"^# recipe: ([^:]+): (.*)$", text, re.M).groups()
args = re.sub(r" --mesh-size \S+", "", args)
small = ["--order", "3", "--mesh-size", "0.25"]
subprocess.run([modes] + shlex.split(args) + small + ["-o", name], check=True, stdout=subprocess.DEVNULL,
               stderr=subprocess.DEVNULL)
open("ring.toml", "w").write(text.replace('"../../out/tables/%s"' % name, '"%s"' % name))
g = float(re.search(r"^gravity = (\S+)", text, re.M).group(1))
rho = float(re.search(r"^density = (\S+)", text, re.M).group(1))
L = float(re.search(r"^scale = (\S+)", text, re.M).group(1))


def one_body_residual(scene_file, sigma, response_args):
    """|Phi(sigma)| of the one-body (22) over the sum of its terms, R(s) by a separate cavity-modes response."""
    body = json.loads(subprocess.run([rom, "spectrum", scene_file, "--json"], capture_output=True, text=True,
                                     check=True).stdout)["bodies"][0]
    A1, C, a, w = body["A_prime"], body["C"], body["a"], body["spin"]
    s = (sigma + w) / w
    subprocess.run([modes] + response_args + ["--sigma", "%.17g%+.17gi" % (s.real, s.imag), "-o", "R.csv"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    row = [l for l in open("R.csv") if l[:1] not in "#s"][0].split(",")
    R = complex(float(row[2]), float(row[3]))
    terms = [A1, C * w / sigma, a * g / sigma ** 2, -rho * L ** 5 * s * R]
    return abs(sum(terms)) / sum(abs(t) for t in terms)


p = subprocess.run([rom, "confirm", "ring.toml", "--json", "--refine-tables", "--cavity-modes", modes],
                   capture_output=True, text=True)
print(p.stderr)
assert p.returncode == 0, p.stderr
res = json.loads(p.stdout)
direct = re.sub(r" --(sigma|max-fit-error) \S+", "", args)
worst = 0.0
for r in res["roots"]:
    sigma = complex(*r["confirmed"])
    e = one_body_residual("ring.toml", sigma, shlex.split(direct) + small)
    worst = max(worst, e)
    print("  %-8s table %s -> confirmed %s: (22) with R by a separate forced solve %.1e" % (
        r["owner"], complex(*r["table"]), sigma, e))
after = [complex(*z) for z in json.loads(subprocess.run([rom, "spectrum", "ring.toml", "--json"], capture_output=True,
                                                         text=True, check=True).stdout)["roots"]]
d = max(min(abs(z - complex(*r["confirmed"])) for z in after) / abs(complex(*r["confirmed"])) for r in res["roots"])
print("viscous ring tank: growth %.6g 1/s confirmed; (22) residual %.1e; refined table's roots to %.1e" % (
    res["growth"], worst, d))
assert worst < 1e-9 and d < 1e-9 and res["growth"] > 0 and not res["stable"], (worst, d, res)

# The ideal twin: no viscosity, the separable table, 40 modes with the static correction.
shape = re.sub(r" --(sigma|max-fit-error|ekman) \S+", "", args).replace("response ", "", 1)
subprocess.run([modes] + shlex.split(shape) + ["--modes", "40", "-o", "ideal.h5"], check=True,
               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
ideal = re.sub(r"^viscosity = .*\n", "", text, flags=re.M).replace('"../../out/tables/%s"' % name, '"ideal.h5"')
ideal = re.sub(r"^center = (.*)$", r"center = \1\nmodes = 40\nstatic_correction = true", ideal, count=1, flags=re.M)
open("ideal.toml", "w").write(ideal)
spec = json.loads(subprocess.run([rom, "spectrum", "ideal.toml", "--json"], capture_output=True, text=True,
                                 check=True).stdout)
assert spec["stable"], "the ideal ring tank's projectile should be stable"
nutation_v = min((complex(*r["confirmed"]) for r in res["roots"]), key=lambda z: z.real)
nearest = min((complex(*z) for z in spec["roots"]), key=lambda z: abs(z - nutation_v))
gap = abs(nearest.real - nutation_v.real) / abs(nutation_v.real)
print("ideal ring tank: stable (%d of %d roots certified real); its nutation %.6f, the viscous one's frequency %.6f "
      "(%.1e apart)" % (spec["certified_real"], len(spec["roots"]), nearest.real, nutation_v.real, gap))
assert spec["certified_real"] == len(spec["roots"]) and gap < 5e-3, (nearest, nutation_v)
print("ok")
