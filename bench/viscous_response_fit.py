#!/usr/bin/env python3
"""The response-fit table in the chain (docs/viscous.md "Response fit", docs/rom.md "Viscous tanks"): one spinning
body with a viscous sphere of fluid (the scene of bench/viscous_chain_response.py), its nutation root from
chain-rom with a response-fit table, against the root of (22) with the fluid's response R(s) computed by a forced
solve AT the complex root itself (cavity-modes response at a complex sigma; no fit, no modes), found by a secant
iteration started at the chain's root. Also the root with the table's single damped mode, for comparison.

  /usr/bin/python3 bench/viscous_response_fit.py [--bin build/modes/cavity-modes] [--rom build/rom/chain-rom]
                                                 [--ekman 1e-3 1e-4]

Samples: every --step (0.05) on [-1.5, 2], and graded towards the spin-over peak at s = 1 (s = 1 + d sinh(u), u every 0.25,
d = 2.6 Ek^1/2 the boundary-layer decay). Writes bench/results/viscous_response_fit_<date>.csv and a markdown table."""
import argparse, os, subprocess, tempfile, time
import numpy as np

from results_csv import write_results
from viscous_chain_response import W, chain_roots, characteristic


def samples(ek, step):
    s = list(np.arange(-1.5, 2.0001, step))
    d = 2.6 * np.sqrt(ek)
    umax = np.arcsinh(0.3 / d)
    s += list(1 + d * np.sinh(np.arange(-umax, umax + 1e-9, 0.25)))
    s = np.unique(np.round(s, 12))
    keep = [s[0]]
    for x in s[1:]:
        if x - keep[-1] > 1e-4 * d:
            keep.append(x)
    return keep


def fit_table(binary, ek, step, path):
    sig = ",".join("%.12g" % x for x in samples(ek, step))
    t0 = time.time()
    p = subprocess.run([binary, "response", "sphere", "--radius", "1", "--ekman", repr(ek), "--sigma", sig,
                        "--max-fit-error", "1e-4", "--fit", "-o", path], capture_output=True, text=True)
    if p.returncode:
        raise SystemExit("Ek %g: %s" % (ek, p.stderr.strip()))
    out = p.stdout
    solver = [l for l in out.splitlines() if l.startswith("solver:")][0]
    return time.time() - t0, len(sig.split(",")), solver


def direct_R(binary, ek, s):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "r.csv")
        subprocess.run([binary, "response", "sphere", "--radius", "1", "--ekman", repr(ek), "--sigma",
                        "%.17g%+.17gi" % (s.real, s.imag), "-o", out], check=True, capture_output=True)
        row = [l for l in open(out) if l[:1] not in "#s"][0].split(",")
    return complex(float(row[2]), float(row[3]))


def secant_root(binary, ek, c_shell, start):
    """(22) with R by a forced solve at every iterate: secant from the chain's root and a point 1e-4 away."""
    x0, x1 = start, start * (1 + 1e-4)
    f0 = characteristic(x0, direct_R(binary, ek, (x0 + W) / W), c_shell)
    f1 = characteristic(x1, direct_R(binary, ek, (x1 + W) / W), c_shell)
    f_start = abs(f0)
    for _ in range(12):
        x2 = x1 - f1 * (x1 - x0) / (f1 - f0)
        x0, f0 = x1, f1
        x1, f1 = x2, characteristic(x2, direct_R(binary, ek, (x2 + W) / W), c_shell)
        if abs(x1 - x0) < 1e-11 * abs(x1):
            break
    return x1, f_start


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default="build/modes/cavity-modes")
    ap.add_argument("--rom", default="build/rom/chain-rom")
    ap.add_argument("--ekman", type=float, nargs="+", default=[1e-3, 1e-4])
    ap.add_argument("--step", type=float, default=0.05, help="uniform sample spacing on the window")
    ap.add_argument("--tag", default="", help="suffix of the results file")
    args = ap.parse_args()
    print("| Ek | samples | fit s | C_shell | root, fit table | root, R by forced solves at it | rel. difference | "
          "growth error | root, damped-mode table |")
    print("|---|---|---|---|---|---|---|---|---|")
    rows = []
    for ek in args.ekman:
        with tempfile.TemporaryDirectory() as d:
            fit = os.path.join(d, "fit.h5")
            modal = os.path.join(d, "modal.h5")
            t_fit, n, solver = fit_table(args.bin, ek, args.step, fit)
            print("<!-- Ek %g: %s -->" % (ek, solver), flush=True)
            subprocess.run([args.bin, "sphere", "--radius", "1", "--ekman", repr(ek), "--modes", "1",
                            "--no-convergence-check", "-o", modal], check=True, capture_output=True)
            for c_shell, s0 in ((0.001, 0.5), (0.004, -1.0)):
                t0 = time.time()
                roots = chain_roots(args.rom, ek, c_shell, fit)
                t_rom = time.time() - t0
                nut = min(roots, key=lambda r: abs((r + W) / W - s0))
                ref, f_start = secant_root(args.bin, ek, c_shell, nut)
                mroots = chain_roots(args.rom, ek, c_shell, modal)
                mnut = max(mroots, key=abs)
                rel = abs(nut - ref) / abs(ref)
                gerr = abs(nut.imag - ref.imag) / abs(ref.imag)
                rows.append(dict(ekman=ek, samples=n, fit_seconds=round(t_fit, 1), C_shell=c_shell,
                                 sigma_fit_re=nut.real, sigma_fit_im=nut.imag, sigma_direct_re=ref.real,
                                 sigma_direct_im=ref.imag, relative_difference=rel, growth_relative_error=gerr,
                                 F_at_fit_root=f_start, spectrum_seconds=round(t_rom, 3), sigma_modal_re=mnut.real,
                                 sigma_modal_im=mnut.imag))
                print("| %.0e | %d | %.0f | %.3f | %.8f %+.8fi | %.8f %+.8fi | %.1e | %.1e | %.4f %+.4fi |" % (
                    ek, n, t_fit, c_shell, nut.real, nut.imag, ref.real, ref.imag, rel, gerr, mnut.real, mnut.imag),
                    flush=True)
    write_results("viscous_response_fit" + args.tag, rows)


if __name__ == "__main__":
    main()
