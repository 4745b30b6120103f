#!/usr/bin/env python3
"""The viscous cone's response R(sigma) under mesh refinement (docs/viscous.md, "Cones"): the 45-degree cone
(radius 1, height 1) at a fixed Ekman number, R at a few frequencies on three meshes, each twice as fine as the
last in the interior and at the wall; prints the changes and the observed order.

  /usr/bin/python3 bench/cone_viscous_response.py [--bin build/modes/cavity-modes] [--ekman 1e-3]
      [--sizes 0.25,0.125,0.0625]

Writes bench/results/cone_viscous_response_Ek<Ek>_<date>.csv."""
import argparse, math, os, subprocess, tempfile, time

from results_csv import write_results

SIGMAS = ["0.5", "1", "1.5", "-0.7", "0.5+0.1i", "1.2+0.05i"]


def run(binary, ek, size, wall):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "r.csv")
        t0 = time.time()
        p = subprocess.run([binary, "response", "cone", "--radius", "1", "--height", "1", "--ekman", repr(ek),
                            "--mesh-size", repr(size), "--wall-size", repr(wall), "--sigma", ",".join(SIGMAS),
                            "-o", out], capture_output=True, text=True)
        if p.returncode:
            raise SystemExit(p.stderr.strip())
        dt = time.time() - t0
        lines = open(out).read().splitlines()
        head = [l for l in lines if l.startswith("# cavity-modes")][0]
        unknowns = head.split(" real unknowns")[0].split("(")[-1]
        R = [complex(float(r.split(",")[2]), float(r.split(",")[3])) for r in lines if r[:1] not in "#s"]
    return R, dt, int(unknowns)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default="build/modes/cavity-modes")
    ap.add_argument("--ekman", type=float, default=1e-3)
    ap.add_argument("--sizes", default="0.25,0.125,0.0625", help="interior sizes, coarse to fine")
    args = ap.parse_args()
    sizes = [float(s) for s in args.sizes.split(",")]
    wall0 = math.sqrt(args.ekman)  # the default first wall element at size 1/8
    rows, results = [], []
    for h in sizes:
        wall = wall0 * h / 0.125
        R, dt, n = run(args.bin, args.ekman, h, wall)
        results.append(R)
        print("size %.4g, wall %.3g: %d real unknowns, %.1f s" % (h, wall, n, dt), flush=True)
        for s, r in zip(SIGMAS, R):
            rows.append(dict(ekman=args.ekman, size=h, wall=wall, unknowns=n, seconds=round(dt, 1), sigma=s,
                             R_re=r.real, R_im=r.imag))
    print("| sigma | R on the finest mesh | change coarse->mid | change mid->fine | observed order |")
    print("|---|---|---|---|---|")
    for j, s in enumerate(SIGMAS):
        r = [res[j] for res in results]
        d1 = abs(r[1] - r[0]) / abs(r[-1])
        d2 = abs(r[2] - r[1]) / abs(r[-1]) if len(r) > 2 else float("nan")
        order = math.log2(d1 / d2) if len(r) > 2 and d2 > 0 else float("nan")
        print("| %s | %.10f %+.10fi | %.2e | %.2e | %.2f |" % (s, r[-1].real, r[-1].imag, d1, d2, order))
    write_results("cone_viscous_response_Ek%g" % args.ekman, rows)


if __name__ == "__main__":
    main()
