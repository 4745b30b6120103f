#!/usr/bin/python3
"""Checks a mode table's /fields and its XDMF companion (cavity-modes --fields, docs/modes.md "Fields").

1. The XDMF parses; every DataItem names an existing dataset of this table, with the XDMF's shape and number
   type; topology, geometry and attributes agree with each other.
2. Mesh: cell indices in range, every sub-triangle positively oriented, 2π ∫∫ r dr dz = the table's volume.
3. Each mode: 2π ∫∫ energy_density dr dz = N² = 1, a = (e1 × r, V) recomputed from the nodal field against
   /modes/a, the members' E against /modes/E. Integrals use the straight sub-triangles and linear
   interpolation of the nodal values (what ParaView shows), so they carry an O((h/P)²) error.
4. --sphere R: the single mode against docs/physics.md §2's closed form p = −z r, V = s (z, −z, −r), s > 0 for N² = 1.
Prints every error; exits 1 on the first failed check.
"""
import argparse
import math
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

failures = []


def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


def check_xdmf(xdmf_path, h5_path):
    root = ET.parse(xdmf_path).getroot()  # raises on malformed XML
    check(root.tag == "Xdmf", "XDMF root element is <Xdmf> (version %s)" % root.get("Version"))
    grids = root.findall("./Domain/Grid")
    check(len(grids) == 1, "one grid in the domain")
    folder = os.path.dirname(os.path.abspath(xdmf_path))
    items = root.iter("DataItem")
    shapes = {}
    with h5py.File(h5_path, "r") as f:
        for item in items:
            check(item.get("Format") == "HDF", "DataItem %s is HDF" % item.text)
            name, _, dataset = item.text.strip().partition(":")
            target = os.path.join(folder, name)
            if not (os.path.exists(target) and os.path.samefile(target, h5_path)):
                check(False, "DataItem file '%s' is the table next to the XDMF" % name)
                continue
            if dataset not in f:
                check(False, "dataset %s exists" % dataset)
                continue
            d = f[dataset]
            dims = tuple(int(x) for x in item.get("Dimensions").split())
            integer = item.get("NumberType") == "Int"
            kind_ok = (d.dtype.kind in "iu") if integer else (d.dtype.kind == "f")
            check(d.shape == dims and kind_ok and d.dtype.itemsize == int(item.get("Precision")),
                  "%s: shape %s dtype %s matches the XDMF (%s %s%s)" %
                  (dataset, d.shape, d.dtype, dims, item.get("NumberType"), item.get("Precision")))
            shapes[dataset] = d.shape
    grid = grids[0]
    topo, geo = grid.find("Topology"), grid.find("Geometry")
    cells = shapes.get(topo.find("DataItem").text.split(":", 1)[1], (0, 0))
    points = shapes.get(geo.find("DataItem").text.split(":", 1)[1], (0, 0))
    check(topo.get("TopologyType") == "Triangle" and int(topo.get("NumberOfElements")) == cells[0] and cells[1] == 3,
          "topology: %d triangles" % cells[0])
    check(geo.get("GeometryType") == "XYZ" and points[1] == 3, "geometry: %d points (XYZ)" % points[0])
    attributes = grid.findall("Attribute")
    for a in attributes:
        shape = shapes.get(a.find("DataItem").text.split(":", 1)[1], ())
        want = (points[0], 3) if a.get("AttributeType") == "Vector" else (points[0],)
        check(a.get("Center") == "Node" and shape == want, "attribute '%s' is nodal, shape %s" % (a.get("Name"), shape))
    return {a.find("DataItem").text.split(":", 1)[1] for a in attributes}


def integrate(points_rz, cells, values):
    """∫∫ values dr dz with linear interpolation on the straight sub-triangles."""
    a, b, c = (points_rz[cells[:, k]] for k in range(3))
    area = 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1]))
    return float(np.sum(area * values[cells].mean(axis=1))), area


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("table")
    ap.add_argument("--sphere", type=float, help="radius: compare with the sphere's closed-form mode")
    ap.add_argument("--tol-integral", type=float, default=1e-2, help="energy integral and volume (relative)")
    ap.add_argument("--tol-a", type=float, default=1e-2, help="a recomputed from the nodal field (relative)")
    ap.add_argument("--tol-closed", type=float, default=1e-2, help="sphere field, max nodal error / max |V|")
    args = ap.parse_args()
    xdmf = os.path.splitext(args.table)[0] + ".xdmf"
    check(os.path.isfile(xdmf), "XDMF companion %s exists" % xdmf)
    if failures:
        return 1
    referenced = check_xdmf(xdmf, args.table)

    with h5py.File(args.table, "r") as f:
        pts = f["fields/mesh/points"][:]
        cells = f["fields/mesh/cells"][:]
        rz = pts[:, [0, 2]]
        check(np.all(pts[:, 1] == 0) and pts[:, 0].min() >= 0, "points are (r >= 0, 0, z)")
        check(cells.min() >= 0 and cells.max() < len(pts), "cell indices in [0, %d)" % len(pts))
        vol, area = integrate(rz, cells, rz[:, 0])
        vol *= 2 * math.pi
        check(area.min() > 0, "every sub-triangle positively oriented (smallest area %.2e)" % area.min())
        err = abs(vol - f.attrs["volume"]) / f.attrs["volume"]
        check(err <= args.tol_integral, "volume from the sub-triangles: rel err %.2e" % err)
        zc = f.attrs["centroid_z"]
        E, a_table = f["modes/E"][:], f["modes/a"][:]
        groups = sorted(k for k in f["fields"] if k.startswith("mode_"))
        check(len(groups) == len(E), "%d mode groups for %d /modes rows" % (len(groups), len(E)))
        for i in range(len(E)):
            g = f["fields/mode_%d" % i]
            check(g.attrs["modes_row"] == i, "mode_%d belongs to /modes row %d" % (i, g.attrs["modes_row"]))
            for name in ("p", "V", "energy_density"):
                check("/fields/mode_%d/%s" % (i, name) in referenced, "mode_%d/%s is in the XDMF" % (i, name))
            V, e = g["V"][:], g["energy_density"][:]
            r, z = rz[:, 0], rz[:, 1] - zc
            e_nodes = (V ** 2).sum(axis=1) * r
            check(np.allclose(e, e_nodes, rtol=1e-12, atol=0), "mode_%d: energy_density = |V|^2 r" % i)
            N2 = 2 * math.pi * integrate(rz, cells, e)[0]
            check(abs(N2 - 1) <= args.tol_integral, "mode_%d: 2 pi int int energy_density = %.6f (err %.2e)" %
                  (i, N2, abs(N2 - 1)))
            # a = (e1 x r, V) = pi int int [z' (v_r - v_phi) - r v_z] r dr dz (docs/physics.md §2, real amplitudes)
            a = math.pi * integrate(rz, cells, (z * (V[:, 0] - V[:, 1]) - r * V[:, 2]) * r)[0]
            err = abs(a - a_table[i]) / a_table[i]
            check(err <= args.tol_a, "mode_%d: a from the nodal field %.6f vs /modes/a %.6f (rel err %.2e)" %
                  (i, a, a_table[i], err))
            err = abs(g.attrs["E_members"] - E[i]) / E[i]
            check(err <= 1e-9, "mode_%d: E of the %d re-solved members vs /modes/E: rel err %.2e" %
                  (i, g.attrs["members"], err))
            err = abs(g.attrs["a"] - a_table[i]) / a_table[i]
            check(err <= 1e-6, "mode_%d: a of the FE field vs /modes/a: rel err %.2e" % (i, err))
        if args.sphere:
            R = args.sphere
            s = math.sqrt(15 / (16 * math.pi * R ** 5))
            r, z = rz[:, 0], rz[:, 1] - zc
            V = f["fields/mode_0/V"][:]
            exact = s * np.stack([z, -z, -r], axis=1)
            err = np.abs(V - exact).max() / np.abs(exact).max()
            check(err <= args.tol_closed, "sphere: V vs s (z, -z, -r), max nodal error / max |V| = %.2e" % err)
            p = f["fields/mode_0/p"][:]
            err = np.abs(p - (-s * z * r)).max() / np.abs(s * z * r).max()
            check(err <= args.tol_closed, "sphere: p vs -s z r, max nodal error / max |p| = %.2e" % err)
    print("%d checks failed" % len(failures) if failures else "all fields checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
