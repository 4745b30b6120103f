#!/usr/bin/env python3
"""Viscous mode tables (cavity-modes --ekman): the Ek -> 0 approach to the boundary-layer limit, error against run
time under mesh refinement, and MPI (-n 1 against -n 2). Writes a CSV and a markdown summary into bench/results/.

  /usr/bin/python3 bench/viscous_bench.py [--bin build/modes/cavity-modes] [--quick]

The boundary-layer limits lambda1 (lambda = lambda0 + lambda1 Ek^1/2 + ...) are the values that
tests/modes/test_viscous.cpp computes from the closed-form ideal modes (Greenspan's formula,
modes/viscous/boundary_layer.hpp)."""
import argparse, csv, datetime, math, os, platform, subprocess, sys, tempfile, time
import h5py

LIMITS = {  # lambda1 (real, imag) from tests/modes/test_viscous.cpp
    "sphere": (0.2584638, 2.6204722),
    "cylinder": (0.053352, 1.447087),
}
SHAPES = {"sphere": ["sphere", "--radius", "1"], "cylinder": ["cylinder", "--radius", "1", "--height", "2"]}
LAMBDA0 = {"sphere": 1.0, "cylinder": 2 / 2.0089710942}


def run(binary, shape, ek, extra=(), mpi=0):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "t.h5")
        cmd = list(SHAPES[shape]) + ["--modes", "1", "--ekman", repr(ek), "--no-convergence-check", "-o", out] + list(extra)
        cmd = [binary] + cmd
        if mpi:
            cmd = ["mpirun", "-n", str(mpi)] + cmd
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        t0 = time.time()
        p = subprocess.run(cmd, capture_output=True, text=True, env=env)
        wall = time.time() - t0
        if p.returncode != 0:
            raise SystemExit(f"{' '.join(cmd)} failed: {p.stderr.strip()}")
        with h5py.File(out) as f:
            m = f["modes"]
            return dict(shape=shape, ek=ek, args=" ".join(extra), mpi=mpi, unknowns=int(f.attrs["ndof"]), wall=wall,
                        lam=float(m["lambda"][0]), decay=float(m["decay"][0]), E=float(m["E"][0]),
                        E_imag=float(m["E_imag"][0]))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default="build/modes/cavity-modes")
    ap.add_argument("--quick", action="store_true", help="Ek down to 1e-5 only")
    a = ap.parse_args()
    rows = []
    eks = [1e-3, 1e-4, 1e-5] + ([] if a.quick else [1e-6])
    for shape in ("sphere", "cylinder"):
        for ek in eks:
            r = run(a.bin, shape, ek)
            r["kind"] = "Ek sweep"
            rows.append(r)
            print(f"{shape} Ek {ek:g}: lambda {r['lam']:.9f} decay {r['decay']:.9f} decay/Ek^1/2 "
                  f"{r['decay'] / math.sqrt(ek):.5f} (limit {LIMITS[shape][1]}), (lambda-lambda0)/Ek^1/2 "
                  f"{(r['lam'] - LAMBDA0[shape]) / math.sqrt(ek):.5f} (limit {LIMITS[shape][0]}), "
                  f"{r['unknowns']} unknowns, {r['wall']:.1f} s", flush=True)
    # Error against run time at Ek = 1e-4: meshes around the default, against the finest.
    for shape in ("sphere", "cylinder"):
        ladder = [("--order", "4", "--mesh-size", "0.25"), ("--order", "6", "--mesh-size", "0.25"), (),
                  ("--order", "6", "--mesh-size", "0.0625")]
        rs = [run(a.bin, shape, 1e-4, l) for l in ladder]
        ref = rs[-1]
        for r in rs:
            r["kind"] = "refinement"
            r["err"] = abs(complex(r["lam"], r["decay"]) - complex(ref["lam"], ref["decay"])) / abs(complex(ref["lam"], ref["decay"]))
            rows.append(r)
            print(f"{shape} Ek 1e-4 [{r['args'] or 'default'}]: lambda error {r['err']:.2e} against the finest, "
                  f"{r['unknowns']} unknowns, {r['wall']:.1f} s", flush=True)
    for n in (1, 2):
        r = run(a.bin, "sphere", 1e-4, (), mpi=n)
        r["kind"] = "mpi"
        rows.append(r)
        print(f"sphere Ek 1e-4 mpirun -n {n}: lambda {r['lam']:.12f} decay {r['decay']:.12f} {r['wall']:.1f} s", flush=True)
    stamp = datetime.date.today().isoformat()
    os.makedirs("bench/results", exist_ok=True)
    path = f"bench/results/viscous_{stamp}.csv"
    keys = ["kind", "shape", "ek", "args", "mpi", "unknowns", "wall", "lam", "decay", "E", "E_imag", "err"]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    print(f"wrote {path} ({platform.node()}, {os.cpu_count()} cores)")


if __name__ == "__main__":
    main()
