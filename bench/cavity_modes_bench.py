#!/usr/bin/python3
"""Error against run time for cavity-modes (issue "error against run time").

Runs the cavity-modes binary over a sweep of --order and --mesh-size for three cavities with closed-form
answers (docs/physics.md §2), compares each table with exact values computed here, independently of the C++
closed forms, and writes

  bench/results/cavity_modes_<date>.csv                one row per run
  bench/results/cavity_modes_error_vs_time.png         relative error vs wall time, a curve per order
  bench/results/cavity_modes_<date>_targets.md         fastest settings meeting each target (timed again)

and prints the observed convergence orders (slope of log error against log h for each element order).

    /usr/bin/python3 bench/cavity_modes_bench.py [BINARY] [--quick] [--repeat N]

Needs Debian's python3-numpy and python3-matplotlib (scripts/install-deps.sh) and python3-scipy (apt-get install python3-scipy).
"""
import argparse
import csv
import datetime
import json
import math
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import functools

import numpy as np
from numpy.polynomial.legendre import leggauss as _leggauss
try:
    from scipy.special import jv
except ImportError:
    sys.exit("cavity_modes_bench.py: needs Debian's python3-scipy: apt-get install python3-scipy "
             "(bench only, so scripts/install-deps.sh leaves it out)")

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)

# ---------------------------------------------------------------------------------------------------------
# Exact values (rho = 1, omega0 = 1), computed here from docs/physics.md §2 and the issue, not from the C++.
# ---------------------------------------------------------------------------------------------------------


@functools.lru_cache(maxsize=None)
def leggauss(n):
    return _leggauss(n)


def _bisect_all(f, lo, hi, iters=54):
    """Vectorised bisection: f(lo) and f(hi) have opposite signs elementwise."""
    flo = f(lo)
    for _ in range(iters):
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        left = np.sign(fm) == np.sign(flo)
        lo = np.where(left, mid, lo)
        flo = np.where(left, fm, flo)
        hi = np.where(left, hi, mid)
    return 0.5 * (lo + hi)


def _roots_on_grid(f, x):
    fx = f(x)
    i = np.nonzero(np.sign(fx[:-1]) * np.sign(fx[1:]) < 0)[0]
    return _bisect_all(f, x[i], x[i + 1])


def stewartson_energy(a, h, k, xi, lam):
    """E = 2 (e1 x r, V)^2 / |V|^2 for p = J1(xi r / a) sin(k z) on r < a, |z| < h (docs/physics.md §2).

    The z integrals are done in closed form (k h = (2n+1) pi / 2, so cos(k h) = 0 and the integrals of sin^2 and
    cos^2 over (-h, h) are both h); (e1 x r, V) uses int_0^a (r J1)_r dr = a J1(q a) and
    int_0^a r^2 J1(q r) dr = a^2 J2(q a) / q; |V|^2 leaves one radial integral, done by Gauss-Legendre.
    """
    q = xi / a
    x, w = leggauss(10 * (int(80 + 3 * xi) // 10 + 1))
    r = 0.5 * a * (x + 1)
    w = 0.5 * a * w
    j1 = jv(1, q * r)
    j1r = q * (jv(0, q * r) - j1 / (q * r))
    D = 4 - lam * lam
    Vr = (lam * j1r + 2 * j1 / r) / D
    Vphi = (2 * j1r + lam * j1 / r) / D
    Vz = k * j1 / lam
    norm2 = 2 * math.pi * h * np.sum((Vr ** 2 + Vphi ** 2 + Vz ** 2) * r * w)
    s = math.sin(k * h)
    coupling = -math.pi * 2 * s * (a * jv(1, q * a) / (k * k * (2 - lam)) + a * a * jv(2, q * a) / (q * lam))
    return 2 * coupling ** 2 / norm2


def cylinder_modes(a, height, max_axial=12, max_xi=120.0):
    """Stewartson's modes: k = (2n+1) pi / (2h), xi J1'(xi) + kappa J1(xi) = 0, xi^2 = (k a)^2 (kappa^2 - 1).

    Returns a list of dicts (kappa, E, n, j) for n < max_axial and xi < max_xi, both signs of kappa,
    sorted by E descending.
    """
    h = height / 2
    grid = np.arange(0.02, max_xi, 0.02)
    out = []
    for n in range(max_axial):
        k = (2 * n + 1) * math.pi / (2 * h)
        ka = k * a
        for sign in (+1, -1):
            # xi J1' = xi J0 - J1, so the condition is xi J0(xi) + (kappa - 1) J1(xi) = 0 on the branch kappa(xi).
            def f(x, ka=ka, sign=sign):
                return x * jv(0, x) + (sign * np.sqrt(1 + x * x / (ka * ka)) - 1) * jv(1, x)

            for j, xi in enumerate(_roots_on_grid(f, grid), start=1):
                kappa = sign * math.sqrt(1 + xi * xi / (ka * ka))
                out.append(dict(kappa=kappa, E=stewartson_energy(a, h, k, xi, 2 / kappa), n=n, j=j, xi=xi))
    out.sort(key=lambda m: -m["E"])
    return out


def cylinder_zhukovsky(a, height, terms=3000):
    """J_zh = m_f [h^2/3 - 3a^2/4 + (8a^3/h) sum_j tanh(xi_j h/a) / (xi_j^3 (xi_j^2 - 1))], J1'(xi_j) = 0."""
    h = height / 2
    mass = math.pi * a * a * height

    def d1(x):
        return jv(0, x) - jv(1, x) / x

    xi = _roots_on_grid(d1, np.arange(0.5, math.pi * (terms + 2), 0.05))[:terms]
    assert len(xi) == terms and abs(xi[0] - 1.8411837813406593) < 1e-12
    s = np.sum(np.tanh(xi * h / a) / (xi ** 3 * (xi ** 2 - 1)))
    s += 1 / (4 * math.pi ** 5 * (terms + 0.75) ** 4)  # tail, xi_j ~ (j + 1/4) pi
    return mass * (h * h / 3 - 3 * a * a / 4 + (8 * a ** 3 / h) * s)


def spheroid_exact(a, c):
    m = 4 * math.pi * a * a * c / 3
    return dict(lam=2 * a * a / (a * a + c * c), E=0.8 * m * a * a * c * c / (a * a + c * c),
                J_zh=m * (a * a - c * c) ** 2 / (5 * (a * a + c * c)))


# ---------------------------------------------------------------------------------------------------------
# Runs
# ---------------------------------------------------------------------------------------------------------

SHAPES = {
    # The mesh method: this script sweeps its --order and --mesh-size (cylinders default to the separable method,
    # measured by bench/separable_cylinder_bench.py).
    "cylinder": ["cylinder", "--radius", "1", "--height", "2", "--method", "mesh"],
    "sphere": ["sphere", "--radius", "1"],
    "spheroid": ["spheroid", "--a", "1", "--c", "0.5"],
    "cone": ["cone", "--radius", "1", "--height", "1"],  # apex half-angle 45 degrees (docs/cones.md)
}

# The cone has no closed form: its band weight is compared with a reference extrapolated from the sweep's own
# finest order-6 meshes (cone_reference). Only the survey is needed for /bands, so the cone runs ask for one
# cluster and no convergence check; its times are those of such a table.
CONE_BANDS = {"cone_band_E": (-0.4, -0.3), "cone_band2_E": (1.4, 1.5)}

SWEEP_ARGS = {"cylinder": ["--modes", "20"], "sphere": [], "spheroid": [],
              "cone": ["--modes", "1", "--no-convergence-check"]}  # the sphere and spheroid: default table
FULL_SWEEP = {  # order -> mesh sizes; finer meshes only where they stay cheap (full sweep ~5 min on 2 cores)
    "cylinder": {2: [0.5, 0.35, 0.25, 0.18, 0.125, 0.09, 0.0625], 3: [0.5, 0.35, 0.25, 0.18, 0.125, 0.09],
                 4: [0.7, 0.5, 0.35, 0.25, 0.18, 0.125, 0.09], 5: [1.0, 0.7, 0.5, 0.35, 0.25, 0.18, 0.125],
                 6: [1.0, 0.7, 0.5, 0.35, 0.25, 0.18, 0.125]},
    "sphere": {2: [0.5, 0.35, 0.25, 0.18, 0.125, 0.09, 0.0625], 3: [0.7, 0.5, 0.35, 0.25, 0.18, 0.125],
               4: [1.0, 0.7, 0.5, 0.35, 0.25, 0.18], 5: [1.0, 0.7, 0.5, 0.35, 0.25], 6: [1.0, 0.7, 0.5, 0.35, 0.25, 0.18]},
    "spheroid": {2: [0.35, 0.25, 0.18, 0.125, 0.09, 0.0625], 3: [0.5, 0.35, 0.25, 0.18, 0.125, 0.09],
                 4: [0.7, 0.5, 0.35, 0.25, 0.18, 0.125, 0.09], 5: [1.0, 0.7, 0.5, 0.35, 0.25, 0.18, 0.125],
                 6: [1.0, 0.7, 0.5, 0.35, 0.25, 0.18, 0.125, 0.09]},
    "cone": {2: [0.4, 0.2, 0.1, 0.05, 0.025], 4: [0.4, 0.2, 0.1, 0.05], 6: [0.4, 0.2, 0.1, 0.05]},
}
QUICK_SWEEP = {
    "cylinder": {2: [0.5, 0.25], 4: [0.7, 0.5]},
    "sphere": {2: [0.5, 0.25], 4: [1.0, 0.5]},
    "spheroid": {2: [0.35, 0.25], 4: [0.7, 0.5]},
    "cone": {4: [0.4, 0.2, 0.1], 6: [0.4, 0.2, 0.1]},  # the reference needs three order-6 meshes
}

ERRORS = {  # CSV column -> panel title
    "cyl_dom_E": "cylinder: dominant E",
    "cyl_dom_kappa": "cylinder: dominant kappa",
    "cyl_top5_E": "cylinder: top-5 E (max)",
    "cyl_top20_E": "cylinder: top-20 E (max)",
    "cyl_J_zh": "cylinder: J_zh",
    "sph_E": "sphere: E",
    "sph_lambda": "sphere: lambda",
    "spd_E": "spheroid a=1 c=0.5: E",
    "spd_lambda": "spheroid: lambda",
    "spd_J_zh": "spheroid: J_zh",
    "cone_band_E": "cone 45deg: band [-0.4,-0.3) weight",
    "cone_band2_E": "cone 45deg: band [1.4,1.5) weight",
}
COLUMNS = (["shape", "order", "mesh_size", "ndof", "clusters", "coverage", "wall_s", "process_s", "user_s", "load1",
            "status"] + list(ERRORS) + ["cyl_top20_kappa", "cyl_exact20_missing", "cyl_top20_worst"]
           + [q + "_value" for q in CONE_BANDS])


def rel(got, want):
    return abs(got - want) / abs(want)


def run_table(binary, shape, order, size, extra=(), timeout=300):
    """Runs one table; returns (info json or None, process wall seconds, status text)."""
    with tempfile.TemporaryDirectory(prefix="cmbench-") as tmp:
        out = os.path.join(tmp, "t.h5")
        cmd = [binary] + SHAPES[shape] + list(extra) + ["--order", str(order), "--mesh-size", repr(size), "-o", out]
        cpu0 = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
        t0 = time.perf_counter()
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, time.perf_counter() - t0, "timeout"
        wall = time.perf_counter() - t0
        user = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - cpu0
        if p.returncode != 0:
            return None, wall, "exit %d: %s" % (p.returncode, p.stderr.strip().splitlines()[-1:] or "")
        info = subprocess.run([binary, "info", out, "--json"], capture_output=True, text=True, check=True)
        t = json.loads(info.stdout)
        t["_user_s"] = user  # user CPU time of the run (the machine may be shared: wall time is noisy)
        return t, wall, "ok"


def nearest(modes, kappa):
    return min(modes, key=lambda m: abs(m["kappa"] - kappa))


def errors_of(shape, t, exact):
    e = {}
    M = t["modes"]
    if shape == "cylinder":
        modes = exact["cyl_modes"]
        dom = modes[0]
        e["cyl_dom_E"] = rel(M["E"][0], dom["E"])
        e["cyl_dom_kappa"] = rel(M["kappa"][0], dom["kappa"])
        errs, kerrs, worst = [], [], ""
        for i, (k, E) in enumerate(zip(M["kappa"][:20], M["E"][:20])):
            m = nearest(modes, k)
            errs.append(rel(E, m["E"]))
            kerrs.append(rel(k, m["kappa"]))
            if errs[-1] == max(errs):
                worst = "#%d kappa %.6g (exact n=%d j=%d E %.3g, got %.3g)" % (i + 1, k, m["n"], m["j"], m["E"], E)
        e["cyl_top5_E"] = max(errs[:5]) if len(errs) >= 5 else float("nan")
        e["cyl_top20_E"] = max(errs) if len(errs) >= 20 else float("nan")
        e["cyl_top20_kappa"] = max(kerrs) if len(kerrs) >= 20 else float("nan")
        e["cyl_top20_worst"] = worst
        # Exact top-20 modes with no computed cluster within 1e-6 relative in kappa.
        e["cyl_exact20_missing"] = sum(
            1 for m in modes[:20] if min(abs(k - m["kappa"]) for k in M["kappa"]) > 1e-6 * abs(m["kappa"]))
        e["cyl_J_zh"] = rel(t["J_zh"], exact["cyl_J_zh"])
    elif shape == "cone":
        # Raw band weights; cone_errors() turns them into errors once the reference is known.
        b = t["bands"]
        for q, (lo, hi) in CONE_BANDS.items():
            i = min(range(len(b["lo"])), key=lambda i: abs(b["lo"][i] - lo) + abs(b["hi"][i] - hi))
            e[q + "_value"] = b["E"][i]
    elif shape == "sphere":
        e["sph_E"] = rel(M["E"][0], 8 * math.pi / 15)
        e["sph_lambda"] = rel(M["lambda"][0], 1.0)
    else:
        x = exact["spheroid"]
        e["spd_E"] = rel(M["E"][0], x["E"])
        e["spd_lambda"] = rel(M["lambda"][0], x["lam"])
        e["spd_J_zh"] = rel(t["J_zh"], x["J_zh"])
    return e


def row_of(shape, order, size, t, wall, status, exact):
    row = dict(shape=shape, order=order, mesh_size=size, process_s=round(wall, 3), status=status,
               load1=round(os.getloadavg()[0], 2))
    if t is not None:
        row.update(ndof=t["ndof"], clusters=len(t["modes"]["E"]), coverage=t["coverage"],
                   wall_s=round(t["wall_seconds"], 3), user_s=round(t["_user_s"], 3))
        row.update(errors_of(shape, t, exact))
    return row


# ---------------------------------------------------------------------------------------------------------
# Analysis
# ---------------------------------------------------------------------------------------------------------

FLOOR = 1e-16  # errors of exactly 0 are plotted here
CEILING = 10.0  # errors above (a cluster matched to a mode it is not) are drawn here
SATURATED = 3e-12  # errors below this are round-off / solver tolerance, left out of the slopes


def fnum(v):
    try:
        v = float(v)
    except (TypeError, ValueError):
        return float("nan")
    return v


ASYMPTOTIC_POINTS = 3  # the asymptotic-range fit uses this many finest unsaturated meshes


def convergence_orders(rows, floors=None):
    """Per (quantity, order): least-squares slope of log(error) against log(h) over all unsaturated points, the
    slope between the two finest of them, their number, and the least-squares slope over the ASYMPTOTIC_POINTS
    finest (the asymptotic range: coarse meshes are often pre-asymptotic). `floors` gives a quantity its own
    saturation level (a reference's own error estimate), default SATURATED."""
    out = {}
    for q in ERRORS:
        floor = max(SATURATED, (floors or {}).get(q, 0.0))
        for order in range(1, 7):
            pts = [(fnum(r["mesh_size"]), fnum(r.get(q))) for r in rows
                   if r["status"] == "ok" and int(r["order"]) == order and not math.isnan(fnum(r.get(q)))]
            pts = [(h, e) for h, e in pts if e > floor]
            if len({h for h, _ in pts}) < 2:
                continue
            pts.sort()
            lh = np.log([h for h, _ in pts])
            le = np.log([e for _, e in pts])
            finest = (le[1] - le[0]) / (lh[1] - lh[0]) if lh[1] != lh[0] else float("nan")
            k = min(ASYMPTOTIC_POINTS, len(pts))
            asym = float(np.polyfit(lh[:k], le[:k], 1)[0])
            out[(q, order)] = (float(np.polyfit(lh, le, 1)[0]), float(finest), len(pts), asym)
    return out


def cone_reference(rows, log):
    """Reference band weights of the cone from the sweep's three finest order-6 meshes (h halved each time):
    Richardson extrapolation with the observed order p = log2(|d1|/|d2|) when the changes d1, d2 have the same
    sign and shrink (p > 0.5); its error estimate is the extrapolation step |ref - finest|. Otherwise the finest
    value, with the last change |d2| as its error estimate. Returns {quantity: (ref, relative error estimate,
    p, method)}."""
    out = {}
    cone = sorted((r for r in rows if r["shape"] == "cone" and r["status"] == "ok" and int(r["order"]) == 6),
                  key=lambda r: -fnum(r["mesh_size"]))
    for q in CONE_BANDS:
        v = [fnum(r.get(q + "_value")) for r in cone]
        hs = [fnum(r["mesh_size"]) for r in cone]
        if len(v) < 3 or abs(hs[-3] / hs[-2] - 2) > 1e-9 or abs(hs[-2] / hs[-1] - 2) > 1e-9:
            log("cone reference for %s: needs three order-6 meshes with h halved (have %s)" % (q, hs))
            continue
        d1, d2 = v[-2] - v[-3], v[-1] - v[-2]
        if d1 * d2 > 0 and abs(d2) < abs(d1) and math.log2(abs(d1 / d2)) > 0.5:
            p = math.log2(abs(d1 / d2))
            ref = v[-1] + d2 / (2 ** p - 1)
            out[q] = (ref, abs(ref - v[-1]) / abs(ref), p, "Richardson, P6 h = %g, %g, %g" % tuple(hs[-3:]))
        else:
            out[q] = (v[-1], abs(d2) / abs(v[-1]), float("nan"), "finest mesh, P6 h = %g (the changes do not shrink steadily: no order to extrapolate with)" % hs[-1])
        log("cone reference %s: %.12e (relative error estimate %.1e, %s, observed order %.2f; values %s)" % (
            q, out[q][0], out[q][1], out[q][3], out[q][2], " ".join("%.10e" % x for x in v[-3:])))
    for r in rows:
        if r["shape"] == "cone" and r["status"] == "ok":
            for q, (ref, _, _, _) in out.items():
                r[q] = rel(fnum(r[q + "_value"]), ref)
    return out


TARGETS = [
    # name, shape, error columns, tolerance, time target (s), extra arguments for the timed re-runs
    ("cylinder dominant E to 1e-8", "cylinder", ["cyl_dom_E"], 1e-8, 1.0, ["--modes", "1"]),
    ("cylinder 20-cluster table, E to 1e-6", "cylinder", ["cyl_top20_E"], 1e-6, 3.0, ["--modes", "20"]),
    ("sphere table, E and lambda to 1e-8", "sphere", ["sph_E", "sph_lambda"], 1e-8, 0.5, []),
    ("spheroid table, E, lambda, J_zh to 1e-8", "spheroid", ["spd_E", "spd_lambda", "spd_J_zh"], 1e-8, 0.5, []),
]


def meets(row, cols, tol):
    return row["status"] == "ok" and all(fnum(row.get(c)) <= tol for c in cols)


def time_targets(binary, rows, exact, repeat, log):
    """For each target: the settings of the sweep that meet its accuracy, the three fastest in the sweep re-run
    `repeat` times (with the target's extra arguments, e.g. --modes 1 for the dominant mode alone); the fastest
    median that still meets the accuracy is reported."""
    results = []
    swept = {r["shape"] for r in rows}
    for name, shape, cols, tol, tmax, extra in TARGETS:
        if shape not in swept:
            continue
        ok = sorted((r for r in rows if r["shape"] == shape and meets(r, cols, tol)), key=lambda r: fnum(r["process_s"]))
        best = None
        for r in ok[:3]:
            walls, procs, good, errs, status = [], [], True, {}, "ok"
            for _ in range(repeat):
                t, wall, status = run_table(binary, shape, int(r["order"]), fnum(r["mesh_size"]), extra)
                if t is None:
                    good = False
                    break
                e = errors_of(shape, t, exact)
                good = good and all(e[c] <= tol for c in cols)
                errs = {c: max(errs.get(c, 0), e[c]) for c in cols}
                walls.append(t["wall_seconds"])
                procs.append(wall)
            if not good:
                log("  %s: order %s h %s fails on re-run (%s; errors %s)" % (name, r["order"], r["mesh_size"], status,
                                                                           errs))
                continue
            log("  %s: order %s h %s%s: program %s s, process %s s" % (
                name, r["order"], r["mesh_size"], " " + " ".join(extra) if extra else "",
                " ".join("%.2f" % w for w in walls), " ".join("%.2f" % w for w in procs)))
            cand = dict(order=int(r["order"]), mesh_size=fnum(r["mesh_size"]), ndof=int(r["ndof"]),
                        wall_s=statistics.median(walls), process_s=statistics.median(procs), errors=errs,
                        extra=" ".join(extra))
            if best is None or cand["process_s"] < best["process_s"]:
                best = cand
        results.append(dict(name=name, shape=shape, tol=tol, tmax=tmax, best=best, extra=" ".join(extra)))
    return results


def targets_markdown(results, rows, repeat):
    lines = ["| target | time target | fastest setting measured | ndof | program wall_seconds (median of %d) "
             "| process wall (median) | errors | met? |" % repeat, "|---|---|---|---|---|---|---|---|"]
    for t in results:
        b = t["best"]
        if b is None:
            lines.append("| %s | < %g s | none in the sweep reaches the accuracy | | | | | **no** |" % (t["name"], t["tmax"]))
            continue
        setting = "--order %d --mesh-size %g%s" % (b["order"], b["mesh_size"], (" " + b["extra"]) if b["extra"] else "")
        errs = ", ".join("%s %.1e" % (c, v) for c, v in b["errors"].items())
        met = "yes" if b["process_s"] < t["tmax"] else (
            "program time only" if b["wall_s"] < t["tmax"] else "**no**")
        lines.append("| %s | < %g s | `%s` | %d | %.2f s | %.2f s | %s | %s |" % (
            t["name"], t["tmax"], setting, b["ndof"], b["wall_s"], b["process_s"], errs, met))
    return "\n".join(lines) + "\n"


def best_errors_markdown(rows):
    """Smallest error each quantity reached in the sweep, and at what cost (for targets nobody meets)."""
    lines = ["| quantity | smallest error in the sweep | setting | process wall |", "|---|---|---|---|"]
    for q, title in ERRORS.items():
        cand = [r for r in rows if r["status"] == "ok" and not math.isnan(fnum(r.get(q)))]
        if not cand:
            continue
        r = min(cand, key=lambda r: fnum(r[q]))
        lines.append("| %s | %.1e | order %s, h %s | %.2f s |" % (title, fnum(r[q]), r["order"], r["mesh_size"],
                                                                  fnum(r["process_s"])))
    return "\n".join(lines) + "\n"


def plot(rows, path, time_col="process_s", floors=None):
    """`floors`: quantity -> the relative error estimate of its reference, drawn as a dotted line."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # Only the quantities of the shapes swept; a cone point whose error is exactly 0 is the reference mesh itself.
    qs = [q for q in ERRORS if any(r["status"] == "ok" and not math.isnan(fnum(r.get(q))) for r in rows)]
    rows = [r for r in rows if not (r["shape"] == "cone" and all(fnum(r.get(q)) == 0 for q in CONE_BANDS))]
    ncol = min(5, len(qs))
    nrow = math.ceil(len(qs) / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 4.4 * nrow), squeeze=False)
    colours = {2: "tab:blue", 3: "tab:orange", 4: "tab:green", 5: "tab:red", 6: "tab:purple"}
    targets = {"cyl_dom_E": (1e-8, 1.0), "cyl_top20_E": (1e-6, 3.0), "sph_E": (1e-8, 0.5), "sph_lambda": (1e-8, 0.5),
               "spd_E": (1e-8, 0.5), "spd_lambda": (1e-8, 0.5), "spd_J_zh": (1e-8, 0.5)}
    for ax, q in zip(axes.flat, qs):
        for order in sorted({int(r["order"]) for r in rows}):
            pts = sorted(((fnum(r[time_col]), max(fnum(r.get(q)), FLOOR), fnum(r["mesh_size"])) for r in rows
                          if r["status"] == "ok" and int(r["order"]) == order and not math.isnan(fnum(r.get(q)))),
                         key=lambda p: -p[2])
            if pts:
                ys = [min(p[1], CEILING) for p in pts]
                ax.loglog([p[0] for p in pts], ys, "o-", ms=3.5, lw=1.2, color=colours.get(order),
                          label="P%d" % order)
                prog = sorted(((fnum(r["wall_s"]), min(max(fnum(r.get(q)), FLOOR), CEILING), fnum(r["mesh_size"]))
                               for r in rows if r["status"] == "ok" and int(r["order"]) == order
                               and not math.isnan(fnum(r.get(q)))), key=lambda p: -p[2])
                ax.loglog([p[0] for p in prog], [p[1] for p in prog], "o--", ms=2.5, lw=0.6, mfc="none",
                          alpha=0.45, color=colours.get(order))
        if q in targets:
            tol, tmax = targets[q]
            ax.axhline(tol, color="grey", ls="--", lw=0.8)
            ax.axvline(tmax, color="grey", ls=":", lw=0.8)
            ax.fill_between([1e-2, tmax], [1e-17, 1e-17], [tol, tol], color="green", alpha=0.07)
        if floors and q in floors:
            ax.axhline(floors[q], color="k", ls=":", lw=0.8)
            ax.text(0.03, floors[q] * 1.5, "reference's own error estimate", fontsize=6, transform=ax.get_yaxis_transform())
        ax.set_title(ERRORS[q], fontsize=10)
        ax.set_ylim(FLOOR / 2, CEILING * 3)
        ax.set_xlim(0.02, None)
        ax.grid(True, which="major", lw=0.4, alpha=0.6)
        ax.tick_params(labelsize=8)
        ax.set_xlabel("wall time [s] (solid: process, dashed: program's wall_seconds)", fontsize=7)
        ax.set_ylabel("relative error", fontsize=8)
    for ax in list(axes.flat)[len(qs):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=8, title="element order", title_fontsize=8)
    fig.suptitle("cavity-modes: relative error vs wall time (points: mesh sizes, coarse to fine; "
                 "shaded: target; 1e-16: exact to rounding; 10: >= 10)", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    fig.savefig(path, dpi=110)


def machine():
    cpu = "?"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    ram = "?"
    try:
        with open("/proc/meminfo") as f:
            kb = int(f.readline().split()[1])
            ram = "%.1f GiB" % (kb / 2 ** 20)
    except OSError:
        pass
    return dict(nproc=os.cpu_count(), cpu=cpu, ram=ram, kernel=platform.release())


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binary", nargs="?", default=os.path.join(REPO, "build/modes/cavity-modes"))
    ap.add_argument("--quick", action="store_true", help="small sweep (smoke run, ~1 min); files get a _quick suffix")
    ap.add_argument("--repeat", type=int, default=3, help="timed re-runs of each target's candidates (0: skip)")
    ap.add_argument("--out-dir", default=os.path.join(HERE, "results"))
    ap.add_argument("--shapes", default="cylinder,sphere,spheroid")
    ap.add_argument("--label", help="what the binary was built from, if not this repository's HEAD "
                                    "(e.g. a clean export of a commit while modes/ is being edited)")
    ap.add_argument("--replot", metavar="CSV", help="only redraw the PNG (next to CSV) from a results CSV")
    ap.add_argument("--tag", help="added to the output file names (a study that must not overwrite the day's sweep)")
    args = ap.parse_args()
    if args.replot:
        with open(args.replot) as f:
            rows = list(csv.DictReader(f))
        # cavity_modes_<date><suffix>.csv -> cavity_modes_error_vs_time<suffix>.png
        suffix = os.path.basename(args.replot)[len("cavity_modes_") + 10:-len(".csv")]
        png = os.path.join(os.path.dirname(os.path.abspath(args.replot)), "cavity_modes_error_vs_time%s.png" % suffix)
        cone_ref = cone_reference(rows, print) if any(r["shape"] == "cone" for r in rows) else {}
        plot(rows, png, floors={q: v[1] for q, v in cone_ref.items()})
        print("wrote", png)
        return
    binary = os.path.abspath(args.binary)
    if not os.access(binary, os.X_OK):
        sys.exit("cavity_modes_bench: %s is not an executable (build with cmake --build build)" % binary)
    os.makedirs(args.out_dir, exist_ok=True)
    log = lambda s: print(s, flush=True)

    t0 = time.perf_counter()
    exact = dict(cyl_modes=cylinder_modes(1.0, 2.0), cyl_J_zh=cylinder_zhukovsky(1.0, 2.0),
                 spheroid=spheroid_exact(1.0, 0.5))
    dom = exact["cyl_modes"][0]
    log("exact values (%.1f s): cylinder dominant kappa %.12f E %.12f (n=%d j=%d); %d Stewartson modes, "
        "J_zh %.12f; spheroid lambda %.6f E %.12f J_zh %.12f; sphere E %.12f" % (
            time.perf_counter() - t0, dom["kappa"], dom["E"], dom["n"], dom["j"], len(exact["cyl_modes"]),
            exact["cyl_J_zh"], exact["spheroid"]["lam"], exact["spheroid"]["E"], exact["spheroid"]["J_zh"],
            8 * math.pi / 15))

    sweep = QUICK_SWEEP if args.quick else FULL_SWEEP
    shapes = args.shapes.split(",")
    stamp = datetime.date.today().isoformat()
    suffix = ("_" + args.tag if args.tag else "") + ("_quick" if args.quick else "")
    commit = subprocess.run(["git", "-C", REPO, "log", "-1", "--format=%h"], capture_output=True, text=True).stdout.strip()
    dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--", "modes", "geometry", "common"],
                           capture_output=True, text=True).stdout.strip()
    if args.label:
        commit, dirty = args.label, ""
    m = machine()
    log("binary %s (repository HEAD %s%s)\nmachine: %d cpus, %s, %s RAM" % (
        binary, commit, ", modes/ has uncommitted edits" if dirty else "", m["nproc"], m["cpu"], m["ram"]))

    rows = []
    for shape in shapes:
        for order, sizes in sweep[shape].items():
            for size in sizes:
                t, wall, status = run_table(binary, shape, order, size, SWEEP_ARGS[shape])
                row = row_of(shape, order, size, t, wall, status, exact)
                rows.append(row)
                errs = "  ".join("%s %.1e" % (q, row[q]) for q in ERRORS if q in row)
                log("%-8s P%d h=%-5g %6s dofs  %6.2f s (program %s)  %s%s" % (
                    shape, order, size, row.get("ndof", "-"), wall, row.get("wall_s", "-"), errs,
                    "" if status == "ok" else "  " + status))
    sweep_s = time.perf_counter() - t0

    cone_ref = cone_reference(rows, log) if "cone" in shapes else {}
    csv_path = os.path.join(args.out_dir, "cavity_modes_%s%s.csv" % (stamp, suffix))
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: ("%.3e" % v if k in ERRORS or k == "cyl_top20_kappa" else v) for k, v in r.items()})
    png_path = os.path.join(args.out_dir, "cavity_modes_error_vs_time%s.png" % suffix)
    plot(rows, png_path, floors={q: v[1] for q, v in cone_ref.items()})
    log("\nwrote %s\nwrote %s\nsweep: %d runs, %.0f s" % (csv_path, png_path, len(rows), sweep_s))

    orders = convergence_orders(rows, {q: 2 * v[1] for q, v in cone_ref.items()})
    conv = ["| quantity | " + " | ".join("P%d" % o for o in range(2, 7)) + " |", "|---" * 6 + "|"]
    for q, title in ERRORS.items():
        cells = []
        for o in range(2, 7):
            s = orders.get((q, o))
            cells.append("%.1f / %.1f (%d) / **%.1f**" % s if s else "-")
        conv.append("| %s | %s |" % (title, " | ".join(cells)))
    conv_md = "\n".join(conv) + "\n"
    conv_md = ("slope of log(error) against log(h): least squares over the points with error > %.0e (cone bands: > "
               "twice the reference's own error estimate) / between the two finest of them (number of points) / "
               "**least squares over the %d finest of them (asymptotic range)**; '-': fewer than two such points\n\n"
               % (SATURATED, ASYMPTOTIC_POINTS)) + conv_md
    log("\nobserved convergence orders\n" + conv_md)
    best_md = best_errors_markdown(rows)
    log("smallest errors reached\n" + best_md)

    if args.repeat > 0:
        results = time_targets(binary, rows, exact, args.repeat, log)
        tmd = targets_markdown(results, rows, args.repeat)
        log("targets\n" + tmd)
    else:
        tmd = "(targets not timed: --repeat 0)\n"
    md_path = os.path.join(args.out_dir, "cavity_modes_%s%s_targets.md" % (stamp, suffix))
    with open(md_path, "w") as f:
        f.write("# cavity-modes benchmark %s%s\n\nbinary: `%s`, repository HEAD %s%s\n\n" % (
            stamp, suffix, binary if os.path.relpath(binary, REPO).startswith("..") else os.path.relpath(binary, REPO),
            commit, " (modes/ had uncommitted edits)" if dirty else ""))
        f.write("machine: %d cpus, %s, %s RAM, Linux %s\n\nsweep: %d runs, %.0f s\n\n" % (
            m["nproc"], m["cpu"], m["ram"], m["kernel"], len(rows), sweep_s))
        if cone_ref:
            f.write("## Cone references\n\n" + "".join(
                "- %s: %.12e, relative error estimate %.1e (%s; observed order %.2f)\n" % (
                    ERRORS[q], v[0], v[1], v[3], v[2]) for q, v in cone_ref.items()) + "\n")
        f.write("## Targets\n\n" + tmd + "\n## Smallest errors reached\n\n" + best_md +
                "\n## Observed convergence orders\n\n" + conv_md)
    log("wrote %s\ntotal %.0f s" % (md_path, time.perf_counter() - t0))


if __name__ == "__main__":
    main()
