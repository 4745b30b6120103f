#!/usr/bin/env python3
"""One spinning body with a viscous sphere of fluid (the scene of tests/rom/test_viscous_chain.cpp): the nutation
root of (22) with the fluid's full response function R(s) (cavity-modes response: a forced solve per frequency,
every mode included) against the root chain-rom finds with the table's single damped spin-over mode, and against the classic boundary-layer
response (Greenspan's Ek^1/2 theory with the Ekman layer driven at the nutation frequency).

  /usr/bin/python3 bench/viscous_chain_response.py [--bin build/modes/cavity-modes] [--rom build/rom/chain-rom]

(22) for one body about its centre of mass, no gravity, spin w, in the table's units s = (sigma + w)/w:
    F(sigma) = A' + C w/sigma - (sigma + w) (rho L^5 / w) R(s) = 0,   R(s) = sum_l E_l/(s - lambda_l).
R is analytic near the real axis (the poles lambda_l have Im > 0), so it is sampled on a short real segment
around the ideal nutation frequency and continued as a polynomial to the complex root (|Im s| ~ 1e-2).
Writes bench/results/viscous_chain_response_<date>.csv and prints a markdown table."""
import argparse, json, os, subprocess, sys, tempfile
import numpy as np
try:
    from scipy.integrate import quad
except ImportError:
    sys.exit("viscous_chain_response.py: needs Debian's python3-scipy: apt-get install python3-scipy "
             "(bench only, so scripts/install-deps.sh leaves it out)")

from results_csv import write_results

RHO, L, W = 1000.0, 0.05, 100.0
A_SHELL = 0.002
AF = 8 * np.pi / 15 * RHO * L**5


def response(binary, ek, lo, hi, n):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "r.csv")
        subprocess.run([binary, "response", "sphere", "--radius", "1", "--ekman", repr(ek),
                        "--sigma", "%r:%r:%d" % (lo, hi, n), "-o", out], check=True, capture_output=True)
        lines = [l for l in open(out) if l[:1] not in "#s"]  # the '#' mesh line and the column names
        data = np.array([[float(x) for x in l.split(",")] for l in lines])
    return data[:, 0], data[:, 2] + 1j * data[:, 3]


def chain_roots(rom, ek, c_shell, table):
    """Every root of the one-body scene with `table` (chain-rom spectrum --json)."""
    with tempfile.TemporaryDirectory() as d:
        scene = os.path.join(d, "s.toml")
        with open(scene, "w") as f:
            f.write('[system]\nkind = "fixed"\ngravity = 0.0\n[[body]]\nmass = 0.5\nA = %r\nC = %r\ncom = 0.0\n'
                    'spin = %r\n[body.cavity]\ntable = "%s"\ndensity = %r\nscale = %r\ncenter = 0.0\n'
                    'viscosity = %r\n' % (A_SHELL, c_shell, W, table, RHO, L, ek * W * L * L))
        j = json.loads(subprocess.run([rom, "spectrum", scene, "--json"], check=True, capture_output=True,
                                      text=True).stdout)
    return [complex(r[0], r[1]) for r in j["roots"]]


def chain_root(rom, ek, c_shell, table):
    return max(chain_roots(rom, ek, c_shell, table), key=abs)


def characteristic(sg, Rs, c_shell):
    """(22) for the one body: A' + C w/sigma - (sigma + w) (rho L^5 / w) R, with R = R(s) given."""
    A, C = A_SHELL + AF, c_shell + AF
    return A + C * W / sg - (sg + W) * RHO * L**5 / W * Rs


def boundary_layer_lambda1(s):
    """Greenspan's Ek^1/2 coefficient for the sphere's spin-over flow, with its Ekman layer driven at the
    frequency s instead of the mode's own lambda0 = 1 (docs/viscous.md section 4: q+- = (i(s +- 2c))^1/2;
    on the wall U_s + iU_phi = cos(theta) - 1, U_s - iU_phi = -1 - cos(theta), c = cos(theta), |V|^2 over the ball
    16 pi/15). At s = 1 it is 0.2585 + 2.6205i, Greenspan's (1968) values."""
    def part(th, k):
        c = np.cos(th)
        v = 0.5 * (np.sqrt(1j * (s + 2 * c)) * (1 - c)**2 + np.sqrt(1j * (s - 2 * c)) * (1 + c)**2) * np.sin(th)
        return v.real if k == 0 else v.imag
    integral = quad(part, 0, np.pi, args=(0,), limit=400)[0] + 1j * quad(part, 0, np.pi, args=(1,), limit=400)[0]
    return 1j * 2 * np.pi * integral / (16 * np.pi / 15)


def boundary_layer_response(ek):
    """R(s) = E/(s - 1 - Ek^1/2 lambda1(s)), E = 8 pi/15: the ideal sphere's single coupling mode with the
    boundary layer at the forcing frequency (other modes couple only at O(Ek))."""
    return lambda s: (8 * np.pi / 15) / (s - 1 - np.sqrt(ek) * boundary_layer_lambda1(s))


def solve(c_shell, R, s0):
    F = lambda sg: characteristic(sg, R((sg + W) / W), c_shell)
    sg = (s0 - 1) * W
    for _ in range(60):
        h = 1e-6 * abs(sg)
        d = (F(sg + h) - F(sg - h)) / (2 * h)
        step = F(sg) / d
        sg -= step
        if abs(step) < 1e-13 * abs(sg):
            break
    return sg


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default="build/modes/cavity-modes")
    ap.add_argument("--rom", default="build/rom/chain-rom")
    args = ap.parse_args()
    print("| Ek | C_shell | root with R(s) (response) | root with the table's damped mode | root with the boundary-layer R(s) | fit |")
    print("|---|---|---|---|---|---|")
    rows = []
    for ek in (1e-3, 1e-4, 1e-5):
        with tempfile.TemporaryDirectory() as d:
            table = os.path.join(d, "t.h5")
            subprocess.run([args.bin, "sphere", "--radius", "1", "--ekman", repr(ek), "--modes", "1",
                            "--no-convergence-check", "-o", table], check=True, capture_output=True)
            for c_shell, s0 in ((0.001, 0.5), (0.004, -1.0)):
                s, r = response(args.bin, ek, s0 - 0.06, s0 + 0.06, 13)
                coef = np.polyfit(s - s0, r, 8)
                fit_err = np.max(np.abs(np.polyval(coef, s - s0) - r)) / np.max(np.abs(r))
                R = lambda x: np.polyval(coef, x - s0)
                full = solve(c_shell, R, s0)
                modal = chain_root(args.rom, ek, c_shell, table)
                layer = solve(c_shell, boundary_layer_response(ek), s0)
                rows.append(dict(ekman=ek, C_shell=c_shell, sigma_response_re=full.real, sigma_response_im=full.imag,
                                 sigma_modal_re=modal.real, sigma_modal_im=modal.imag, sigma_layer_re=layer.real,
                                 sigma_layer_im=layer.imag, fit_error=fit_err))
                print("| %.0e | %.3f | %.6f %+.6fi | %.6f %+.6fi | %.6f %+.6fi | %.1e |" % (
                    ek, c_shell, full.real, full.imag, modal.real, modal.imag, layer.real, layer.imag, fit_err), flush=True)
    write_results("viscous_chain_response", rows)


if __name__ == "__main__":
    main()
