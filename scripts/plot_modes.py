#!/usr/bin/python3
"""Draws a cavity-modes table as a PNG: its clusters (E against lambda) and a mode's kinetic-energy density.

    /usr/bin/python3 scripts/plot_modes.py TABLE.h5 [--mode i] -o OUT.png

Panel 1: every /modes row as a stem at its lambda, E on a log scale; filled markers for clusters flagged
converged, open ones for the others (all filled, and said so, if the table has no convergence flags).
Panel 2 (only if the table has /fields, i.e. was written with --fields): mode i's kinetic-energy density
(|v_r|^2 + |v_phi|^2 + |v_z|^2) r on the meridian (r, z), per unit dr dz, so that 2 pi times its integral
is N^2 = 1 (docs/modes.md "Fields"). i is the /modes row, 0-based (default 0: the mode of largest E).
Uses Debian's python3-h5py, python3-matplotlib and python3-numpy.
"""
import argparse
import os
import sys


def fail(message):
    print(f"plot_modes: error: {message}", file=sys.stderr)
    return 1


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("table", help="mode table (HDF5) written by cavity-modes")
    ap.add_argument("--mode", type=int, default=None, help="/modes row whose field to draw (default 0)")
    ap.add_argument("--log", action="store_true",
                    help="draw log10 of the energy density (shows thin Ekman and shear layers of viscous modes)")
    ap.add_argument("-o", "--output", required=True, help="PNG to write")
    args = ap.parse_args()
    try:
        import h5py
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy as np
    except ImportError as e:
        return fail(f"{e} (apt-get install python3-h5py python3-matplotlib python3-numpy)")

    try:
        with h5py.File(args.table, "r") as f:
            if f.attrs.get("format", b"") not in (b"cavity-mode-table", "cavity-mode-table"):
                raise ValueError("not a mode table (root attribute format != cavity-mode-table)")
            lam, E = f["modes/lambda"][:], f["modes/E"][:]
            decay = f["modes/decay"][:] if "modes/decay" in f else None
            converged = f["modes/converged"][:] if "modes/converged" in f else None
            shape = f.attrs["shape"]
            shape = shape.decode() if isinstance(shape, bytes) else str(shape)
            coverage = float(f.attrs["coverage"])
            field = None
            if "fields" in f:
                i = 0 if args.mode is None else args.mode
                if not 0 <= i < len(E):
                    raise ValueError(f"--mode {i} is outside the table's rows 0..{len(E) - 1}")
                g = f[f"fields/mode_{i}"]
                pts = f["fields/mesh/points"][:]
                field = (i, pts[:, 0], pts[:, 2], f["fields/mesh/cells"][:], g["energy_density"][:])
            elif args.mode is not None:
                raise ValueError("no /fields in this table (write it with cavity-modes ... --fields)")
    except (OSError, KeyError, ValueError) as e:
        return fail(f"{args.table}: {e}")
    if len(E) == 0:
        return fail(f"{args.table}: the table has no modes")

    fig, axes = plt.subplots(1, 2 if field else 1, figsize=(12 if field else 7, 5), dpi=110, squeeze=False)
    ax = axes[0][0]
    floor = 10 ** np.floor(np.log10(max(E.min(), 1e-300)) - 1)
    ax.vlines(lam, floor, E, color="0.5", lw=1)
    if converged is None:
        ax.plot(lam, E, "o", color="tab:blue", ms=5, label="cluster (table has no convergence flags)")
    else:
        ok = converged == 1
        if ok.any():
            ax.plot(lam[ok], E[ok], "o", color="tab:blue", ms=6, label="converged")
        if (~ok).any():
            ax.plot(lam[~ok], E[~ok], "o", mfc="white", mec="tab:blue", ms=6, label="not converged")
    if field:
        ax.plot(lam[field[0]], E[field[0]], "o", mfc="none", mec="tab:red", mew=1.5, ms=13,
                label=f"mode {field[0]} (right)")
    ax.set_yscale("log")
    ax.set_ylim(floor, 3 * E.max())
    ax.set_xlim(-2, 2)
    ax.set_xlabel("λ / ω0")
    ax.set_ylabel("E (ρ = 1, table length unit)")
    ax.set_title(f"{os.path.basename(args.table)}: {shape}, {len(E)} cluster{'s' if len(E) > 1 else ''}, coverage {coverage:.4f}")
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="best", fontsize=8)
    if field:
        i, r, z, cells, e = field
        ax = axes[0][1]
        label = "(|v_r|² + |v_φ|² + |v_z|²) r   (2π ∫∫ · dr dz = 1)"
        if args.log:
            e = np.log10(np.maximum(e, e.max() * 1e-6))
            label = "log10 " + label
        im = ax.tripcolor(r, z, cells, e, shading="gouraud", cmap="viridis")
        fig.colorbar(im, ax=ax, label=label)
        ax.set_aspect("equal")
        ax.set_xlabel("r")
        ax.set_ylabel("z")
        damped = f" + {decay[i]:.4g}i (damped)" if decay is not None else ""
        ax.set_title(f"mode {i}: λ = {lam[i]:.6g}{damped}, E = {E[i]:.4g}")
    fig.tight_layout()
    tmp = args.output + f".tmp-{os.getpid()}.png"
    try:
        fig.savefig(tmp)
        os.replace(tmp, args.output)
    except OSError as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        return fail(f"{args.output}: {e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
