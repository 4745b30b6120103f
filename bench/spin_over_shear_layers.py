"""The sphere's viscous spin-over mode against rigid rotation (docs/viscous.md, "Fields").

Runs `cavity-modes sphere --radius 1 --ekman Ek --modes 1 --fields` at Ek = 1e-3, 1e-4, 1e-5, fits the ideal
spin-over field (rigid rotation about a horizontal axis: (V_r, V_phi, V_z) = c (-i z, z, i r) e^{i phi}) to each
damped mode inside r^2 + z^2 < 0.7^2, prints the relative deviation, and draws |V - c V_rigid| on the meridian:
the internal shear layers spawned where the Ekman layer is singular (the critical latitude, where the
characteristics of lambda = 1 touch the wall) show up as rays.

    /usr/bin/python3 bench/spin_over_shear_layers.py [BINARY] [-o PNG]
"""
import argparse
import os
import subprocess
import tempfile

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

EKMAN = ["1e-3", "1e-4", "1e-5"]


def deviation(path):
    with h5py.File(path, "r") as f:
        g, pts = f["fields/mode_0"], f["fields/mesh/points"][:]
        r, z = pts[:, 0], pts[:, 2]
        V = g["V"][:] + 1j * g["V_imag"][:]
        rigid = np.stack([-1j * z, z + 0j, 1j * r], axis=1)
        inner = r ** 2 + z ** 2 < 0.7 ** 2
        v, w = V[inner].ravel(), rigid[inner].ravel()
        c = np.vdot(w, v) / np.vdot(w, w)
        rel = np.linalg.norm(v - c * w) / np.linalg.norm(v)
        lam = complex(f["modes/lambda"][0], f["modes/decay"][0])
        return r, z, f["fields/mesh/cells"][:], np.linalg.norm(V - c * rigid, axis=1) / abs(c), rel, lam


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("binary", nargs="?", default="build/modes/cavity-modes")
    ap.add_argument("-o", "--output", default="docs/figures/sphere_spin_over_shear_layers.png")
    a = ap.parse_args()
    fig, axes = plt.subplots(1, 3, figsize=(12, 4.8), dpi=100)
    with tempfile.TemporaryDirectory() as d:
        for ax, ek in zip(axes, EKMAN):
            path = os.path.join(d, "s%s.h5" % ek)
            subprocess.run([a.binary, "sphere", "--radius", "1", "--ekman", ek, "--modes", "1", "--fields",
                            "--no-convergence-check", "-o", path], check=True, capture_output=True)
            r, z, cells, dev, rel, lam = deviation(path)
            print("Ek %s: lambda %.6f + %.6fi; interior (r^2 + z^2 < 0.49) deviation from rigid rotation %.3f"
                  % (ek, lam.real, lam.imag, rel))
            im = ax.tripcolor(r, z, cells, dev, shading="gouraud", cmap="magma", vmax=1.0)
            ax.set_aspect("equal")
            ax.set_title("Ek = %s: |V - c V_rigid| / |c|\ninterior deviation %.2f" % (ek, rel), fontsize=10)
            ax.set_xlabel("r")
        axes[0].set_ylabel("z")
        fig.colorbar(im, ax=list(axes), shrink=0.8)
    fig.savefig(a.output)
    print("wrote", a.output)


if __name__ == "__main__":
    main()
