#!/usr/bin/env python3
"""The fields of a 3-D ellipsoid table (cavity-modes ellipsoid --fields) against the closed form of its spin-over mode
(docs/volume.md §3): with semi-axes D = diag(a, b, c) the mode is a uniform-vorticity flow V = D [w]x D^-1 r, with
K (i lambda) w = -2 D [D^-1 Omega]x w (Omega = z, upright) and K = diag((b2+c2)/(bc), (a2+c2)/(ac), (a2+b2)/(ab)).

Checks, each printed with its error:
  * the XDMF companion parses and names datasets of the sizes it states; cells are tetrahedra of positive volume;
  * the heaviest row's V is linear in position (least squares V = L r + v0, relative residual);
  * L is D [w]x D^-1 for one complex w (relative residual of that fit) and w solves the closed form's eigenproblem at
    the table's lambda (relative residual), lambda itself against 2ab / sqrt((a2+c2)(b2+c2));
  * int |V|^2 = 1 (exactly, for a linear field: sum_jk |L_jk|^2 m D_k^2 / 5) and a = u^H c from the same L.
A row's field is one discrete mode; a 3-D mesh splits the spin-over among discrete copies a little apart in lambda
(docs/volume.md §3), so the heaviest row's field is the closed form up to the copies' share: its departure from a
linear field is judged against --tol-linear (default 0.1), the rest against --tol (default 5e-3).
Usage: check_volume_fields.py TABLE.h5 A B C [--tol T] [--tol-linear T]
"""
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np


def cross_matrix(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]], dtype=complex)


def check(name, err, tol):
    ok = err < tol
    print(("ok: " if ok else "FAILED: ") + f"{name}: {err:.2e} (tolerance {tol:.0e})")
    return ok


def xdmf_items(xdmf_path, h5):
    """Every DataItem of the companion exists in the table with the dimensions stated."""
    worst = 0
    for item in ET.parse(xdmf_path).iter("DataItem"):
        dims = tuple(int(x) for x in item.attrib["Dimensions"].split())
        dataset = item.text.split(":", 1)[1]
        worst = max(worst, 0 if h5[dataset].shape == dims else 1)
    return worst


def main():
    path, a, b, c = sys.argv[1], *map(float, sys.argv[2:5])
    tol = float(sys.argv[sys.argv.index("--tol") + 1]) if "--tol" in sys.argv else 5e-3
    tol_linear = float(sys.argv[sys.argv.index("--tol-linear") + 1]) if "--tol-linear" in sys.argv else 0.1
    D = np.diag([a, b, c])
    f = h5py.File(path, "r")
    good = check("XDMF companion names datasets of the stated sizes", xdmf_items(path[:-3] + ".xdmf", f), 0.5)
    x = f["fields/mesh/points"][()]
    cells = f["fields/mesh/cells"][()]
    e = x[cells[:, 1:]] - x[cells[:, :1]]
    vol = np.linalg.det(e) / 6
    good &= check("sub-tetrahedra of positive volume (smallest / mean)", 0 if vol.min() > 0 else 1, 0.5)
    good &= check("sub-tetrahedra fill the ellipsoid (volume against 4/3 pi abc)",
                  abs(vol.sum() / (4 / 3 * np.pi * a * b * c) - 1), 2e-2)
    E = f["modes/E"][()]
    row = int(np.argmax(E))
    g = f[f"fields/mode_{row}"]
    lam = f["modes/lambda"][row]
    V = g["V"][()] + 1j * g["V_imag"][()]
    A = np.hstack([x, np.ones((len(x), 1))])
    coef, *_ = np.linalg.lstsq(A, V, rcond=None)
    L, v0 = coef[:3].T, coef[3]
    good &= check("V is linear in position (residual / |V|; the discrete copies' share)", np.linalg.norm(A @ coef - V) / np.linalg.norm(V), tol_linear)
    # L = D [w]x D^-1 is linear in w: solve for w by least squares over the 9 entries.
    basis = np.array([(D @ cross_matrix(np.eye(3)[k]) @ np.linalg.inv(D)).ravel() for k in range(3)]).T
    w, *_ = np.linalg.lstsq(basis, L.ravel(), rcond=None)
    good &= check("L = D [w]x D^-1 (residual / |L|)", np.linalg.norm(basis @ w - L.ravel()) / np.linalg.norm(L), tol)
    K = np.diag([(b * b + c * c) / (b * c), (a * a + c * c) / (a * c), (a * a + b * b) / (a * b)])
    rhs = -2 * D @ cross_matrix(np.linalg.inv(D) @ np.array([0, 0, 1.0])) @ w
    good &= check("closed form: i lambda K w = -2 D [D^-1 z]x w (residual / |K w|)",
                  np.linalg.norm(1j * lam * K @ w - rhs) / np.linalg.norm(lam * K @ w), tol)
    exact = 2 * a * b / np.sqrt((a * a + c * c) * (b * b + c * c))
    good &= check("lambda against 2ab/sqrt((a2+c2)(b2+c2))", abs(lam - exact) / exact, tol)
    m = 4 / 3 * np.pi * a * b * c
    norm2 = sum(abs(L[j, k]) ** 2 * m * D[k, k] ** 2 / 5 for j in range(3) for k in range(3))
    good &= check("int |V|^2 = 1 from the fitted linear field", abs(norm2 - 1), tol)
    # c_k = int (e_k x r).V = int r^T [e_k]x^T L r = trace([e_k]x^T L m D^2 / 5); a = u^H c with u the top axis of H.
    cvec = np.array([np.trace(cross_matrix(np.eye(3)[k]).T @ L @ (m * D @ D / 5)) for k in range(3)])
    H = (f["volume/coupling_re"][()] + 1j * f["volume/coupling_im"][()]).reshape(-1, 3, 3)[row]
    vals, vecs = np.linalg.eigh(H)
    u = vecs[:, -1]
    good &= check("a = u^H c from the fitted field, against the stored a", abs(abs(np.vdot(u, cvec)) - g.attrs["a"]) / g.attrs["a"], tol)
    good &= check("a^2 against the row's largest coupling eigenvalue", abs(g.attrs["a"] ** 2 - vals[-1]) / vals[-1], tol)
    print(f"spin-over row {row}: lambda {lam:.10f} (exact {exact:.10f}), w = {np.round(w / np.linalg.norm(w), 6)}")
    sys.exit(0 if good else 1)


if __name__ == "__main__":
    main()
