#!/usr/bin/python3
"""Error against run time of the partially filled tank's mesh method: the dense solver (every pair) up to 4000
unknowns, two levels beyond (the rows of the mesh with its sizes doubled, then SLEPc near them on the fine mesh).

Two closed forms: the cylinder (radius 1, height 2) filled to 0.9, whose heaviest frequency is Stewartson's
0.9828689768884 (13 digits: docs/physics.md §2), and the sphere filled to 0.4, whose one coupled mode is the rigid turn: λ = 1 and
E = A_f + K2 (the table's sum rule, J_zh = 0 there). Each run is `cavity-modes SHAPE --fill F [--method mesh] --mesh-size H
--no-convergence-check --modes 4`, timed on the wall clock. Writes

  bench/results/free_surface_solvers_<date>.csv   one row per run
  bench/results/free_surface_solvers_<date>.png   error of λ1 against run time, dense and two-level marked

    /usr/bin/python3 bench/free_surface_solvers.py [BINARY]

Needs Debian's python3-h5py and python3-matplotlib (scripts/install-deps.sh).
"""
import csv
import datetime
import os
import subprocess
import sys
import tempfile
import time

import h5py

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(REPO, "scripts"))
import plotting  # noqa: E402  (scripts/plotting.py: the plots' shared helper)

CASES = [
    ("cylinder", ["cylinder", "--radius", "1", "--height", "2", "--method", "mesh"], "0.9", 0.9828689768884, [0.5, 0.35, 0.25, 0.18, 0.12, 0.085]),
    ("sphere", ["sphere", "--radius", "1"], "0.4", 1.0, [0.24, 0.17, 0.12, 0.085, 0.06]),
]


def run(binary, args, fill, size, out):
    start = time.monotonic()
    r = subprocess.run([binary] + args + ["--fill", fill, "--mesh-size", str(size), "--no-convergence-check",
                                          "--modes", "4", "-o", out], capture_output=True, text=True)
    seconds = time.monotonic() - start
    if r.returncode != 0:
        raise SystemExit(f"cavity-modes failed: {r.stderr.strip()}")
    with h5py.File(out, "r") as f:
        lam, E = float(f["modes/lambda"][0]), float(f["modes/E"][0])
        rule, ndof = float(f.attrs["sum_rule"]), int(f.attrs["ndof"])
        solver = f.attrs["solver"]
        solver = solver.decode() if isinstance(solver, bytes) else str(solver)
    return seconds, lam, E, rule, ndof, "two-level" if "SLEPc" in solver else "dense"


def main():
    binary = sys.argv[1] if len(sys.argv) > 1 else os.path.join(REPO, "build", "modes", "cavity-modes")
    date = datetime.date.today().isoformat()
    rows = []
    with tempfile.TemporaryDirectory(prefix="fsbench-") as tmp:
        for name, args, fill, exact, sizes in CASES:
            for size in sizes:
                seconds, lam, E, rule, ndof, solver = run(binary, args, fill, size, os.path.join(tmp, "t.h5"))
                row = dict(shape=name, fill=fill, mesh_size=size, pressure_dofs=ndof, solver=solver,
                           seconds=round(seconds, 2), lambda1=f"{lam:.15f}", lambda_error=f"{abs(lam - exact) / exact:.2e}",
                           E1=f"{E:.12g}", E_error=f"{abs(E - rule) / rule:.2e}" if name == "sphere" else "")
                rows.append(row)
                print(", ".join(f"{k} {v}" for k, v in row.items()), flush=True)
    out = os.path.join(HERE, "results", f"free_surface_solvers_{date}.csv")
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    plt, _ = plotting.pyplot("free_surface_solvers.py")
    if plt is None:
        return 1
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, marker in (("cylinder", "o"), ("sphere", "s")):
        for solver, color in (("dense", "tab:blue"), ("two-level", "tab:red")):
            pts = [(r["seconds"], max(float(r["lambda_error"]), 1e-16)) for r in rows
                   if r["shape"] == name and r["solver"] == solver]
            if pts:
                ax.loglog(*zip(*pts), marker=marker, color=color, linestyle="-", label=f"{name}, {solver}")
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel("relative error of the heaviest λ")
    ax.set_title(f"partially filled tanks, mesh method ({date})")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    code = plotting.save(fig, os.path.join(HERE, "results", f"free_surface_solvers_{date}.png"), "free_surface_solvers.py")
    print(f"wrote {out}")
    return code


if __name__ == "__main__":
    sys.exit(main())
