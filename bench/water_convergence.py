#!/usr/bin/env python3
"""The cylinder and the spheroid at water's Ekman numbers: convergence studies of the dominant (coupling) mode under
mesh refinement, and the converged decay against the boundary-layer limit. There is no spectral peer for these
shapes (Kore does spheres and shells), so each case is judged against our own finest mesh and against
lambda = lambda0 + lambda1 Ek^1/2 + ... (docs/viscous.md section 4).

  /usr/bin/python3 bench/water_convergence.py [--bin build/modes/cavity-modes] [--ekmans 1e-5 1e-6]

Per shape and Ekman number: the uniform interior (--near-wall-size 0), the table's default mesh (the near-wall zone
(Ek d)^1/3 at Ek <= 1e-5, docs/viscous.md "Near-wall zone"), the default command with its convergence check, the
same with --refine 2, and two finer meshes (the interior halved with the zone; the zone halved), the finer of which is
the reference and their difference its uncertainty. Serial, one thread, the whole process's wall clock. Writes
bench/results/water_convergence_<date>.csv and .png (decay error against run time) and prints the boundary-layer
table (decay/Ek^1/2, and one Richardson step between the two Ekman numbers against lambda1)."""
import argparse, csv, datetime, math, os, subprocess, tempfile, time
import h5py

LIMITS = {  # lambda1 from the closed-form ideal modes (tests/modes/test_viscous.cpp, docs/viscous.md section 4)
    "cylinder": complex(0.05335, 1.44709),
    "spheroid": complex(1.42835, 3.03187),
}
SHAPES = {"cylinder": (["cylinder", "--radius", "1", "--height", "2"], 1.0),  # (arguments, smallest dimension d)
          "spheroid": (["spheroid", "--a", "1", "--c", "0.5"], 0.5)}
ENV = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")


def run(binary, shape, args, check=False):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "t.h5")
        cmd = [binary] + SHAPES[shape][0] + ["--modes", "1", "-o", out] + args
        if not check:
            cmd.append("--no-convergence-check")
        t0 = time.time()
        p = subprocess.run(["/usr/bin/time", "-f", "%M"] + cmd, capture_output=True, text=True, env=ENV)
        wall = time.time() - t0
        if p.returncode != 0:
            raise SystemExit(f"{' '.join(cmd)} failed: {p.stderr.strip()[-400:]}")
        with h5py.File(out) as f:
            m = f["modes"]
            conv = int(m["converged"][0]) if "converged" in m and len(m["converged"]) else -1
            return dict(unknowns=int(f.attrs["ndof"]), seconds=round(wall, 2),
                        memory_gb=round(int(p.stderr.strip().splitlines()[-1]) / 1e6, 2),
                        lam=float(m["lambda"][0]), decay=float(m["decay"][0]), E=float(m["E"][0]),
                        E_imag=float(m["E_imag"][0]), converged={-1: "", 0: "NO", 1: "yes"}[conv])


def ideal_lambda(binary, shape):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "t.h5")
        subprocess.run([binary] + SHAPES[shape][0] + ["--modes", "1", "--no-convergence-check", "-o", out], check=True,
                       capture_output=True, env=ENV)
        with h5py.File(out) as f:
            return float(f["modes"]["lambda"][0])


def ladder(ek, d):
    zone = (ek * d) ** (1 / 3)
    interior = d / 8
    return [("uniform interior (--near-wall-size 0)", ["--near-wall-size", "0"], False),
            ("default mesh", [], False),
            ("default command (with its check)", [], True),
            ("--refine 2", ["--refine", "2"], True),
            ("interior h/2 with the zone", ["--mesh-size", repr(interior / 2), "--near-wall-size", repr(zone)], False),
            ("zone halved (reference)", ["--near-wall-size", repr(zone / 2)], False)]


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    markers = {"uniform": "x", "default mesh": "o", "default command": "s", "--refine": "D", "interior": "^"}
    rows = [r for r in rows if not r["setting"].startswith("zone halved")]  # the reference itself
    for key in sorted({(r["shape"], r["ekman"]) for r in rows}):
        pts = [r for r in rows if (r["shape"], r["ekman"]) == key and r["decay_error"] not in ("", None)]
        line = ax.plot([float(p["seconds"]) for p in pts], [max(float(p["decay_error"]), 1e-12) for p in pts], ":",
                       label=f"{key[0]}, Ek {key[1]}")[0]
        for p in pts:
            m = next(v for k, v in markers.items() if p["setting"].startswith(k) or k in p["setting"])
            ax.plot(float(p["seconds"]), max(float(p["decay_error"]), 1e-12), m, color=line.get_color())
    for k, v in markers.items():
        ax.plot([], [], v, color="k", label=k)
    ax.axhline(1e-5, color="grey", lw=0.8)
    ax.set_xscale("log"); ax.set_yscale("log")
    ax.set_xlabel("run time, s (serial, 2-core AMD EPYC)")
    ax.set_ylabel("relative decay error against the zone-halved mesh")
    ax.set_title("Dominant mode at water's Ekman numbers: error against run time")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    print("wrote", path)


def boundary_layer_table(rows):
    """The references against lambda = lambda0 + lambda1 Ek^1/2 + ..., and one Richardson step between two Ekman
    numbers (a next term of O(Ek^1/2) relative: exact for the cylinder, without critical latitudes)."""
    print("\nboundary-layer limit (the references):")
    for shape in SHAPES:
        refs = [r for r in rows if r["shape"] == shape and r["setting"].startswith("zone halved")]
        slopes, eks = [], []
        for ref in refs:
            ek = float(ref["ekman"])
            s = (complex(float(ref["lam"]), float(ref["decay"])) - float(ref["lambda0"])) / math.sqrt(ek)
            slopes.append(s)
            eks.append(ek)
            print(f"  {shape} Ek {ek:g}: (lambda - lambda0)/Ek^1/2 = {s.real:.5f}{s.imag:+.5f}i, limit "
                  f"{LIMITS[shape].real:.5f}{LIMITS[shape].imag:+.5f}i (gap in the decay {s.imag / LIMITS[shape].imag - 1:.2%})")
        if len(slopes) == 2:
            h1, h2 = (math.sqrt(e) for e in eks)
            x = (slopes[1] * h1 - slopes[0] * h2) / (h1 - h2)
            print(f"  {shape}: one Richardson step: {x.real:.5f}{x.imag:+.5f}i, "
                  f"{abs(x - LIMITS[shape]) / abs(LIMITS[shape]):.1e} from lambda1")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default="build/modes/cavity-modes")
    ap.add_argument("--ekmans", nargs="+", type=float, default=[1e-5, 1e-6])
    ap.add_argument("--plot", metavar="CSV", help="only the PNG and the boundary-layer table, from an earlier CSV")
    a = ap.parse_args()
    if a.plot:
        with open(a.plot) as f:
            rows = list(csv.DictReader(f))
        plot(rows, a.plot[:-4] + ".png")
        boundary_layer_table(rows)
        return
    rows = []
    for shape, (_, d) in SHAPES.items():
        lam0 = ideal_lambda(a.bin, shape)
        for ek in a.ekmans:
            runs = []
            for name, args, check in ladder(ek, d):
                r = run(a.bin, shape, ["--ekman", repr(ek)] + args, check)
                r.update(shape=shape, ekman=f"{ek:g}", setting=name, args=" ".join(args))
                runs.append(r)
                print(f"{shape} Ek {ek:g} {name}: lambda {r['lam']:.10f} decay {r['decay']:.10e} "
                      f"E {r['E']:.8f}{r['E_imag']:+.3e}i {r['converged']} {r['unknowns']} unknowns "
                      f"{r['seconds']} s {r['memory_gb']} GB", flush=True)
            ref, finer = runs[-1], runs[-2]
            for r in runs:
                r["lambda0"] = f"{lam0:.13f}"
                r["lambda_error"] = f"{abs(complex(r['lam'], r['decay']) - complex(ref['lam'], ref['decay'])) / abs(complex(ref['lam'], ref['decay'])):.2e}"
                r["decay_error"] = f"{abs(r['decay'] - ref['decay']) / ref['decay']:.2e}"
            ref["reference_uncertainty"] = f"{abs(finer['decay'] - ref['decay']) / ref['decay']:.2e}"
            rows += runs
    stem = f"bench/results/water_convergence_{datetime.date.today().isoformat()}"
    keys = ["shape", "ekman", "lambda0", "setting", "args", "unknowns", "seconds", "memory_gb", "lam", "decay", "E", "E_imag",
            "converged", "lambda_error", "decay_error", "reference_uncertainty"]
    with open(stem + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    print("wrote", stem + ".csv")
    plot(rows, stem + ".png")
    boundary_layer_table(rows)

if __name__ == "__main__":
    main()
