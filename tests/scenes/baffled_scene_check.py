#!/usr/bin/env python3
"""The example with a baffled tank end to end (data/scenes/spacecraft_baffled_tank.toml; docs/volume.md §6).

  baffled_scene_check.py CAVITY_MODES CHAIN_ROM SCENE REPO_ROOT DIR

The scene's recipe (a user's OpenCASCADE .geo with four radial plates, its mesh graded towards the plates' edges)
makes the tank's 3-D table, and the same recipe on a coarser mesh (--mesh-size 0.4) a second; chain-rom spectrum --json
runs the scene on each. No closed form exists for this tank, so the check is the one a user would make: both chains
are stable, each table's band weights (what the scene's reduction = "bands" takes) sum to A_f - J_zh, and the nutation — the one positive root between the two rigid limits
computed here from each table's tensors (the whole liquid frozen; only its Zhukovsky part carried) — agrees between the
two meshes to 1e-3 (measured 2026-11-27: 3.2e-5; 1.5e-4 against P3, docs/volume.md §6)."""
import json, math, os, re, shlex, subprocess, sys
import h5py
import numpy as np

modes, rom, scene, root, out = sys.argv[1:6]
os.makedirs(out, exist_ok=True)
os.chdir(out)
text = open(scene).read()
name, args = re.search(r"^# recipe: ([^:]+): (.*)$", text, re.M).groups()
args = shlex.split(args)
args[1] = os.path.join(root, args[1])  # the .geo file, relative to the repository in the recipe


def table(h, file):
    a = list(args)
    a[a.index("--mesh-size") + 1] = str(h)
    subprocess.run([modes] + a + ["-o", file], check=True, stdout=subprocess.DEVNULL)
    with h5py.File(file) as f:
        v = f["volume"]
        t = {k: v[k][()].reshape(3, 3) for k in ("inertia", "zhukovsky")}
        t["bands"] = abs(float(np.sum(f["bands/E"][()])) / float(f.attrs["sum_rule"]) - 1)
        return t


def nutation_bracket(t):
    """The free body's nutation sigma = spin sqrt((C - A)(C - B)/(A B)) in the turning frame, with the liquid's
    transverse inertia wholly carried (frozen) or only its Zhukovsky part; the spin carries the whole liquid."""
    body = {k: float(re.search(r"^%s = (\S+)" % k, text, re.M).group(1)) for k in ("A", "B", "C", "spin")}
    scale = float(re.search(r"^scale = (\S+)", text, re.M).group(1))
    rho = float(re.search(r"^density = (\S+)", text, re.M).group(1))
    f = rho * scale ** 5
    C = body["C"] + f * t["inertia"][2, 2]
    out = []
    for tensor in ("inertia", "zhukovsky"):
        A, B = body["A"] + f * t[tensor][0, 0], body["B"] + f * t[tensor][1, 1]
        out.append(body["spin"] * math.sqrt((C - A) * (C - B) / (A * B)))
    return sorted(out)


failed = 0
nutation = []
for h, file in ((0.3, name), (0.4, "coarse.h5")):
    t = table(h, file)
    rule = t["bands"]  # the band weights hold the whole transverse coupling, A_f - J_zh
    open("scene.toml", "w").write(text.replace('"../../out/tables/%s"' % name, '"%s"' % file))
    s = json.loads(subprocess.run([rom, "spectrum", "scene.toml", "--json"], capture_output=True, text=True,
                                  check=True).stdout)
    roots = [complex(*r) for r in s["roots"]]
    lo, hi = nutation_bracket(t)
    inside = [r.real for r in roots if lo < r.real < hi]
    print("mesh %.1f: model %s, stable %s, %d roots, band weights against A_f - J_zh %.1e, rigid limits of the nutation %.4f and %.4f rad/s, "
          "roots between them %s" % (h, s["model"], s["stable"], len(roots), rule, lo, hi,
                                     ", ".join("%.6f" % r for r in inside)))
    if s["model"] != "general" or not s["stable"] or rule > 1e-10 or len(inside) != 1:
        print("FAILED: expected the general chain, stable, the band weights summing to A_f - J_zh, and one nutation "
              "root between the limits")
        failed += 1
    nutation += inside[:1]
if len(nutation) == 2:
    d = abs(nutation[0] / nutation[1] - 1)
    print("nutation %.6f rad/s (mesh 0.3) against %.6f (mesh 0.4): %.1e relative" % (nutation[0], nutation[1], d))
    if not d < 1e-3:
        print("FAILED: the nutation moved by more than 1e-3 between the meshes"); failed += 1
sys.exit(1 if failed else 0)
